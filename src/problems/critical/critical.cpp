#include "superpack/problems/critical/critical.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "critical_box.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/geometry/superball.hpp"
#include "superpack/problems/best/best.hpp"
#include "superpack/solve/branch_and_bound.hpp"

namespace superpack {

const char* box_reason_name(BoxReason reason) {
    switch (reason) {
        case BoxReason::no_configuration: return "no_configuration";
        case BoxReason::relabelled: return "relabelled";
        case BoxReason::volume: return "volume";
        case BoxReason::short_vector: return "short_vector";
        case BoxReason::determinant: return "determinant";
        case BoxReason::closing_region: return "closing_region";
        case BoxReason::symmetric: return "symmetric";
        case BoxReason::undecided_width: return "undecided_width";
        case BoxReason::undecided_budget: return "undecided_budget";
        case BoxReason::undecided_contract: return "undecided_contract";
    }
    return "?";
}

bool decided(BoxReason reason) {
    return reason != BoxReason::undecided_width && reason != BoxReason::undecided_budget &&
           reason != BoxReason::undecided_contract;
}

std::vector<ChartBox<DInterval>> top_level_domain() {
    const DoubleField field;
    const DInterval half = field.rational(Rational(1, 2));
    const std::array<DInterval, 2> halves{hull(field.integer(0), half), hull(half, field.integer(1))};
    const DInterval side = hull(field.integer(-1), field.integer(1));
    std::vector<ChartBox<DInterval>> boxes;
    for (const MinkowskiCase configuration : {MinkowskiCase::a3, MinkowskiCase::w})
        for (int face2 = 0; face2 < cube_faces; ++face2)
            for (int face3 = face2; face3 < cube_faces; ++face3)
                for (int piece = 0; piece < 4; ++piece) {
                    ChartBox<DInterval> box;
                    box.configuration = configuration;
                    box.face2 = face2;
                    box.face3 = face3;
                    box.x = {halves[piece / 2], halves[piece % 2], side, side, side, side};
                    boxes.push_back(box);
                }
    return boxes;
}

void require_split(int split) {
    if (split < 0 || split > max_split) throw InputError("--split: 0 to " + std::to_string(max_split) + ", got " + std::to_string(split));
}

std::vector<ChartBox<DInterval>> split_domain(int split) {
    require_split(split);
    return split_start_boxes(top_level_domain(), split, split_box);
}

ChartBox<DInterval> chart_box_around(const DoubleBasis& basis, MinkowskiCase configuration, double half_width) {
    ChartBox<DInterval> box;
    box.configuration = configuration;
    const DInterval like(0.0);
    // A centre off the range by rounding (a guess of 1 + 1e-16) is moved onto it first.
    auto clipped = [&](double centre, double lo, double hi) {
        centre = std::min(hi, std::max(lo, centre));
        return from_doubles(like, std::max(lo, centre - half_width), std::min(hi, centre + half_width));
    };
    box.x[0] = clipped(basis[0][1] / basis[0][0], 0, 1);
    box.x[1] = clipped(basis[0][1] > 0 ? basis[0][2] / basis[0][1] : 0, 0, 1);
    for (int k = 1; k < 3; ++k) {
        int axis = 0;
        for (int j = 1; j < 3; ++j)
            if (std::fabs(basis[k][j]) > std::fabs(basis[k][axis])) axis = j;
        (k == 1 ? box.face2 : box.face3) = 2 * axis + (basis[k][axis] < 0 ? 1 : 0);
        const double scale = std::fabs(basis[k][axis]);
        box.x[2 * k] = clipped(basis[k][axis == 0 ? 1 : 0] / scale, -1, 1);
        box.x[2 * k + 1] = clipped(basis[k][axis == 2 ? 1 : 2] / scale, -1, 1);
    }
    return box;
}

void require_critical_domain(const Rational& p, const Rational& gap) {
    if (!(p > Rational(1, 2)) || p > Rational(10))
        throw InputError("critical: p must satisfy 1/2 < p <= 10 (2K is smooth and strictly convex for p > 1/2; the "
                         "chart is measured up to 10)");
    if (gap < Rational(0) || !(gap < Rational(1, 2))) throw InputError("critical: --gap must satisfy 0 <= gap < 1/2");
    if (p == Rational(1) && gap == Rational(0))
        throw InputError("critical: at p = 1 the densest lattices form a continuum (rotations of FCC), so no box around "
                         "them closes: give --gap G > 0");
}

CriticalReference<DInterval> critical_reference(const Rational& p, const DoubleField& field) {
    const BestLattice<DInterval> best = find_best_lattice(p, field, BestOptions{});
    CriticalReference<DInterval> reference;
    if (best.status != Outcome::proved) throw std::runtime_error("critical: best found no certified packing: " + best.message);
    reference.name = best_name(best);
    reference.phi = best_phi(best);
    reference.basis = best_basis(best);
    reference.optimum = best.local;
    return reference;
}

namespace {

constexpr std::size_t kept_undecided = 20;

// The chart boxes of half-width `radius` around the images of the setup's closing regions.
std::vector<ChartBox<DInterval>> boxes_around_images(const CriticalResult<DInterval>& setup, double radius) {
    if (setup.images.empty())
        throw InputError("critical --around: the best lattice at this p has no closing region in the chart (NOTES.md 12.7)");
    std::vector<ChartBox<DInterval>> boxes;
    for (const ChartImage& image : setup.images) boxes.push_back(chart_box_around(image.chart_basis, image.configuration, radius));
    return boxes;
}

// critical's driver of the branch and bound: one box is decided by critical_box, and a leaf is
// the box with its reason (decided or not); the first few undecided ones are kept.
struct CriticalDriver {
    using Box = ChartBox<DInterval>;
    using Leaf = UndecidedBox<DInterval>;
    BoxContext context;
    std::vector<Leaf> undecided;

    Examined<Box, Leaf> examine(const Box& box, Visit& visit) const {
        const BoxDecision decision = decide_box(box, context, visit.letters);
        if (decision.reason) return leaf_of<Box>(Leaf{box, *decision.reason});
        if (visit.letters) *visit.letters += std::string{'S', static_cast<char>('0' + split_coordinate(decision.box))};
        return split_of<Box, Leaf>(decision.box);
    }
    std::array<Box, 2> split(const Box& box) const { return split_box(box); }
    Leaf unexamined(const Box& box) const { return Leaf{box, BoxReason::undecided_budget}; }
    std::size_t reason(const Leaf& leaf) const { return static_cast<std::size_t>(leaf.reason); }
    void collect(Leaf&& leaf) {
        if (!decided(leaf.reason) && undecided.size() < kept_undecided) undecided.push_back(std::move(leaf));
    }
};

// A count under an index that is no BoxReason would vanish from the undecided ones, so it is a bug.
template <class Counts>
std::array<long, box_reasons> reason_counts(const Counts& counts) {
    if (counts.size() > static_cast<std::size_t>(box_reasons)) throw std::logic_error("critical: a leaf's reason is no BoxReason");
    std::array<long, box_reasons> by_reason{};
    for (std::size_t r = 0; r < counts.size(); ++r) by_reason[r] = counts[r];
    return by_reason;
}

}  // namespace

CriticalResult<DInterval> critical_setup(const CriticalReference<DInterval>& reference, const CriticalOptions& options) {
    const DoubleField field;
    CriticalResult<DInterval> result;
    result.reference = reference;
    const DInterval p = field.rational(options.p);
    result.volume = enclose_ball_volume(p, 3);
    const DInterval reference_det = abs(determinant(reference.basis));
    DInterval threshold = lower_point(reference_det * (field.integer(1) - field.rational(options.gap)));

    // Closing regions around the reference's critical lattice (when it is a certified local
    // optimum), and their images in the chart.
    if (reference.optimum && reference.optimum->verdict == Outcome::proved) {
        result.regions.push_back(certify_closing_region(*reference.optimum, p, options.region_radius, 6));
        if (result.regions.back().verdict == Outcome::proved) {
            std::vector<ChartImage> images = chart_images(result.regions.back(), 0);
            result.images.insert(result.images.end(), images.begin(), images.end());
            // det >= det B* on the region: T may not exceed it.
            const DInterval region_det = lower_point(result.regions.back().determinant);
            if (certainly_less(region_det, threshold)) threshold = region_det;
        }
    }
    // The bound V(K) / T is a density only while T >= V(K), which the checker requires: a gap
    // above 1 - phi of the best lattice can give no valid proof, so it is refused before any box.
    if (certainly_less(threshold, lower_point(result.volume)))
        throw InputError("critical: --gap " + rational_text(options.gap) + " is too large at p = " + rational_text(options.p) +
                         ": T = (1 - gap) |det| falls below V(K), and V(K) / T would exceed 1; the gap must be at most 1 - phi "
                         "of the best lattice, " + to_decimal(field.integer(1) - reference.phi, 4).lo + " here");
    result.threshold = threshold;
    result.upper_phi = upper_point(result.volume / threshold);
    result.relative_gap = upper_point(result.upper_phi / lower_point(reference.phi) - field.integer(1));
    return result;
}

CriticalResult<DInterval> critical_bound(const CriticalReference<DInterval>& reference, const CriticalOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    CriticalResult<DInterval> result = critical_setup(reference, options);
    const std::vector<ChartBox<DInterval>> domain = options.around > 0          ? boxes_around_images(result, options.around)
                                                    : options.start_boxes.empty() ? split_domain(options.split)
                                                                                  : options.start_boxes;
    result.partial_domain = options.shards > 1 || !options.start_boxes.empty() || options.around > 0;

    CriticalDriver driver{box_context(options.p, result.volume, result.threshold, result.regions, result.images, options.min_width), {}};
    BranchOptions search;
    search.threads = std::max(1, options.threads);
    search.max_boxes = options.max_boxes;
    search.shard = options.shard;
    search.shards = options.shards;
    search.record_trees = options.record_trees;
    if (options.progress)
        search.progress = [&](const BranchProgress& progress) {
            options.progress(CriticalProgress{progress.processed, progress.queued, reason_counts(progress.counts), progress.seconds});
        };
    BranchResult<ChartBox<DInterval>> search_result = branch_and_bound(driver, domain, search);

    result.start_boxes = static_cast<long>(search_result.starts.size());
    if (options.record_trees) result.boxes = search_result.starts;
    result.counts = reason_counts(search_result.counts);
    result.processed = search_result.processed;
    result.undecided = driver.undecided;
    long undecided = 0;
    for (int r = 0; r < box_reasons; ++r)
        if (!decided(static_cast<BoxReason>(r))) undecided += result.counts[r];
    if (undecided == 0) {
        result.status = Outcome::proved;
        if (options.record_trees) result.trees = std::move(search_result.trees);
        result.message = result.partial_domain
                             ? "every box of this part of the domain is decided: on it every lattice packing has |det| >= T"
                             : "every box is decided: every lattice packing of K has |det| >= T, so density <= V(K) / T";
    } else {
        result.message = std::to_string(undecided) + " boxes undecided, so no bound is proved";
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

void require_shard_cover(const std::vector<ShardSummary>& shards) {
    if (shards.empty()) throw InputError("critical --merge: no shard results given");
    const int count = shards.front().count;
    std::vector<bool> seen(static_cast<std::size_t>(count), false);
    for (const ShardSummary& shard : shards) {
        if (shard.split != shards.front().split)
            throw InputError("critical --merge: shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) +
                             " was run at --split " + std::to_string(shard.split) + ", the first at " +
                             std::to_string(shards.front().split));
        if (shard.count != count)
            throw InputError("critical --merge: shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) +
                             " is not one of " + std::to_string(count) + " shards");
        if (seen[static_cast<std::size_t>(shard.index)])
            throw InputError("critical --merge: shard " + std::to_string(shard.index) + "/" + std::to_string(count) + " given twice");
        seen[static_cast<std::size_t>(shard.index)] = true;
    }
    std::string missing;
    for (int k = 0; k < count; ++k)
        if (!seen[static_cast<std::size_t>(k)]) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    if (!missing.empty())
        throw InputError("critical --merge: shards missing of " + std::to_string(count) + ": " + missing.substr(0, 200));
}

CriticalResult<DInterval> merge_shards(CriticalResult<DInterval> setup, const std::vector<ShardSummary>& shards) {
    require_shard_cover(shards);
    const int count = shards.front().count;
    std::vector<int> unproved;
    setup.partial_domain = false;
    setup.start_boxes = 0;
    for (const ShardSummary& shard : shards) {
        if (!shard.proved) unproved.push_back(shard.index);
        for (int r = 0; r < box_reasons; ++r) setup.counts[r] += shard.counts[r];
        setup.processed += shard.processed;
        setup.start_boxes += shard.start_boxes;
        setup.seconds += shard.seconds;
    }
    if (!unproved.empty()) {
        setup.status = Outcome::undecided;
        setup.message = std::to_string(unproved.size()) + " of " + std::to_string(count) +
                        " shards undecided (the first: " + std::to_string(unproved.front()) + "), so no bound is proved";
    } else {
        setup.status = Outcome::proved;
        setup.message = "every box of all " + std::to_string(count) +
                        " shards is decided: every lattice packing of K has |det| >= T, so density <= V(K) / T";
    }
    return setup;
}

}  // namespace superpack
