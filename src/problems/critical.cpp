#include "superpack/problems/critical.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "critical_box.hpp"
#include "superpack/geometry/superball.hpp"
#include "superpack/problems/best.hpp"

namespace superpack {

const char* box_reason_name(BoxReason reason) {
    switch (reason) {
        case BoxReason::no_configuration: return "no_configuration";
        case BoxReason::relabelled: return "relabelled";
        case BoxReason::volume: return "volume";
        case BoxReason::short_vector: return "short_vector";
        case BoxReason::determinant: return "determinant";
        case BoxReason::closing_region: return "closing_region";
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
    std::vector<ChartBox<DInterval>> boxes = top_level_domain();
    for (int level = 0; level < split; ++level) {
        std::vector<ChartBox<DInterval>> halves;
        for (const ChartBox<DInterval>& box : boxes)
            for (const ChartBox<DInterval>& half : split_box(box)) halves.push_back(half);
        boxes.swap(halves);
    }
    return boxes;
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

// One work queue shared by the threads: a stack of boxes (depth first keeps it short). The
// leaves' reasons do not depend on the order, so the counts are the same for any number of
// threads unless the budget is reached.
struct WorkQueue {
    std::mutex mutex;
    std::condition_variable wake;
    std::vector<ChartBox<DInterval>> stack;
    // With record_trees: each stacked box's place in its tree (the start box's index in 6 digits,
    // then 0 or 1 per split), and each decided box's place and letters. Sorted by place, the
    // letters are the trees in pre-order.
    bool record = false;
    std::vector<std::string> places;
    std::vector<std::pair<std::string, std::string>> records;
    int active = 0;
    long processed = 0;
    std::array<long, box_reasons> counts{};
    std::vector<UndecidedBox<DInterval>> undecided;
    bool finished = false;
};

constexpr std::size_t kept_undecided = 20;

// The place of start box k: its index in 6 digits, so that places sort by box first.
std::string tree_place(std::size_t k) {
    std::string digits = std::to_string(k);
    return std::string(6 - std::min<std::size_t>(6, digits.size()), '0') + digits;
}

// The chart boxes of half-width `radius` around the images of the setup's closing regions.
std::vector<ChartBox<DInterval>> boxes_around_images(const CriticalResult<DInterval>& setup, double radius) {
    if (setup.images.empty())
        throw InputError("critical --around: the best lattice at this p has no closing region in the chart (NOTES.md 12.7)");
    std::vector<ChartBox<DInterval>> boxes;
    for (const ChartImage& image : setup.images) boxes.push_back(chart_box_around(image.chart_basis, image.configuration, radius));
    return boxes;
}

// The records sorted by place are each tree in pre-order (a place sorts before its extensions,
// and '0' before '1').
std::vector<std::string> assemble_trees(std::vector<std::pair<std::string, std::string>>& records, std::size_t count) {
    std::sort(records.begin(), records.end());
    std::vector<std::string> trees(count);
    for (const auto& record : records) trees[std::stoul(record.first.substr(0, 6))] += record.second;
    return trees;
}

void work(WorkQueue& queue, const BoxContext& context, long max_boxes) {
    std::unique_lock<std::mutex> lock(queue.mutex);
    for (;;) {
        queue.wake.wait(lock, [&] { return !queue.stack.empty() || queue.active == 0; });
        if (queue.stack.empty()) {
            queue.finished = true;
            queue.wake.notify_all();
            return;
        }
        ChartBox<DInterval> box = queue.stack.back();
        queue.stack.pop_back();
        std::string place;
        if (queue.record) {
            place = std::move(queue.places.back());
            queue.places.pop_back();
        }
        const bool over_budget = queue.processed >= max_boxes;
        ++queue.processed;
        ++queue.active;
        lock.unlock();
        std::string letters;
        const BoxDecision decision = over_budget ? BoxDecision{BoxReason::undecided_budget, box}
                                                 : decide_box(box, context, queue.record ? &letters : nullptr);
        const std::optional<BoxReason>& reason = decision.reason;
        std::array<ChartBox<DInterval>, 2> halves;
        if (!reason) {
            halves = split_box(decision.box);
            letters += 'S';
        }
        lock.lock();
        if (queue.record) {
            if (!reason) {
                queue.places.push_back(place + '1');
                queue.places.push_back(place + '0');
            }
            queue.records.emplace_back(std::move(place), std::move(letters));
        }
        --queue.active;
        if (reason) {
            ++queue.counts[static_cast<int>(*reason)];
            if (!decided(*reason) && queue.undecided.size() < kept_undecided) queue.undecided.push_back({box, *reason});
        } else {
            queue.stack.push_back(halves[1]);
            queue.stack.push_back(halves[0]);
        }
        queue.wake.notify_all();
    }
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
    result.threshold = threshold;
    result.upper_phi = upper_point(result.volume / threshold);
    result.relative_gap = upper_point(result.upper_phi / lower_point(reference.phi) - field.integer(1));
    return result;
}

CriticalResult<DInterval> critical_bound(const CriticalReference<DInterval>& reference, const CriticalOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    CriticalResult<DInterval> result = critical_setup(reference, options);
    WorkQueue queue;
    const std::vector<ChartBox<DInterval>> domain = options.around > 0          ? boxes_around_images(result, options.around)
                                                    : options.start_boxes.empty() ? split_domain(options.split)
                                                                                  : options.start_boxes;
    for (std::size_t k = 0; k < domain.size(); ++k)
        if (static_cast<int>(k % static_cast<std::size_t>(options.shards)) == options.shard) queue.stack.push_back(domain[k]);
    result.partial_domain = options.shards > 1 || !options.start_boxes.empty() || options.around > 0;
    result.start_boxes = static_cast<long>(queue.stack.size());
    std::reverse(queue.stack.begin(), queue.stack.end());
    queue.record = options.record_trees;
    if (queue.record) {
        result.boxes.assign(queue.stack.rbegin(), queue.stack.rend());
        for (std::size_t k = queue.stack.size(); k-- > 0;) queue.places.push_back(tree_place(k));
    }

    const BoxContext context =
        box_context(options.p, result.volume, result.threshold, result.regions, result.images, options.min_width);
    std::vector<std::thread> threads;
    for (int t = 0; t < std::max(1, options.threads); ++t)
        threads.emplace_back([&] { work(queue, context, options.max_boxes); });
    std::thread monitor;
    if (options.progress)
        monitor = std::thread([&] {
            std::unique_lock<std::mutex> lock(queue.mutex);
            while (!queue.wake.wait_for(lock, std::chrono::seconds(2), [&] { return queue.finished; })) {
                CriticalProgress progress;
                progress.processed = queue.processed;
                progress.queued = static_cast<long>(queue.stack.size());
                progress.counts = queue.counts;
                progress.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                lock.unlock();
                options.progress(progress);
                lock.lock();
            }
        });
    for (std::thread& thread : threads) thread.join();
    if (monitor.joinable()) monitor.join();

    result.counts = queue.counts;
    result.processed = queue.processed;
    result.undecided = queue.undecided;
    long undecided = 0;
    for (int r = 0; r < box_reasons; ++r)
        if (!decided(static_cast<BoxReason>(r))) undecided += result.counts[r];
    if (undecided == 0) {
        result.status = Outcome::proved;
        if (queue.record) result.trees = assemble_trees(queue.records, result.boxes.size());
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
