// superpack critical: a certified upper bound on the lattice packing density of the superball
// at p (NOTES.md section 12), by interval branch and bound over Minkowski's configurations of a
// critical lattice of 2K in the chart of problems/critical/critical_chart.hpp.
//
// Every box of the domain ends as a leaf with one reason:
//   no_configuration  an equation of the configuration has one sign on the box (no lattice of
//                     the configuration there),
//   relabelled        a configuration vector is certainly longer in the max norm than b1 (the
//                     lattice is covered where it is relabelled, 12.2),
//   volume            |det| < V(K) on the box's configuration points: density > 1, no packing,
//   short_vector      a lattice vector c B with |c_i| <= 2 has 2p-norm < 2 on the whole box,
//   determinant       |det| > T on the box's configuration points (mean-value bound of a
//                     Lagrangian det - sum lambda_i g_i, equal to det where every g_i = 0),
//   closing_region    the box maps into a closing region of a certified local minimiser
//                     (problems/critical/closing_region.hpp), where det >= det B* >= T,
//   symmetric         the box lies outside the fundamental domain of the relabellings that
//                     keep b1 (12.2): a2 > a3 where v2 and v3 share a face, or, for A3,
//                     b1 . (b2 + b3) < |b1|^2 (the lattice is covered where it is relabelled),
//   undecided_width / undecided_budget / undecided_contract: not decided (then the answer is
//                     undecided, never proved).
// If every leaf is decided, every lattice packing of K has |det| >= T, so its density is at
// most V(K) / T: the "upper" bound. T = (1 - gap) |det| of the best certified lattice (the
// "lower" bound on the densest packing's density), lowered to det B* of each closing region.
#pragma once
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "superpack/problems/critical/closing_region.hpp"
#include "superpack/problems/critical/critical_chart.hpp"

namespace superpack {

enum class BoxReason {
    no_configuration,
    relabelled,
    volume,
    short_vector,
    determinant,
    closing_region,
    symmetric,
    undecided_width,
    undecided_budget,
    undecided_contract,
};
constexpr int box_reasons = 10;
const char* box_reason_name(BoxReason reason);
bool decided(BoxReason reason);

template <class I>
struct ChartBox {
    MinkowskiCase configuration = MinkowskiCase::a3;
    int face2 = 0, face3 = 0;
    std::array<I, chart_dimension> x;
    int depth = 0;
    // The coordinate to split this box at (decide_box's choice from its last round's forms,
    // NOTES.md 12.3), or -1: the widest (the rule of split_domain).
    int split = -1;
};

// The top-level boxes of the whole domain, in a fixed order: both configurations, every pair of
// faces of v2 and v3 with face2 <= face3 (swapping b2 and b3 is a relabelling of both
// configurations that keeps b1: NOTES 12.2), and the b1 triangle's square (s, t) in [0, 1]^2 cut
// into 2 x 2. Shard i of n takes those whose index is i mod n.
constexpr int top_level_boxes = 2 * (cube_faces * (cube_faces + 1) / 2) * 4;
std::vector<ChartBox<DInterval>> top_level_domain();

// The start boxes of a run at --split K: each top-level box bisected K times by the branch and
// bound's own rule (the median of the widest coordinate, NOTES.md 12.8), in order: top-level box
// by top-level box, the lower half first. 2^K of them per top-level box, so that a shard's
// certificate stays below the checker's file limit (one top-level box at p = 2 has 178,519 boxes,
// about 16 MB of tree) and the shards' work is spread.
constexpr int max_split = 8;
void require_split(int split);  // InputError unless 0 <= split <= max_split
std::vector<ChartBox<DInterval>> split_domain(int split);

// The chart box of half-width h around a basis already in the chart's normal form (b1 in the
// cone, b1[0] its largest entry; v2, v3 on the faces of their largest entries), clipped to the
// chart's ranges: where tests and benchmarks start, around the images of a minimiser.
ChartBox<DInterval> chart_box_around(const DoubleBasis& basis, MinkowskiCase configuration, double half_width);

// The lattice the bound is measured against: the densest lattice packing superpack certifies at
// p (`best`), and its certified local optimality when there is one.
template <class I>
struct CriticalReference {
    std::string name;
    I phi;
    Basis<I> basis;
    std::optional<LocalOptimum<I>> optimum;
};
CriticalReference<DInterval> critical_reference(const Rational& p, const DoubleField& field);

struct CriticalProgress {
    long processed = 0, queued = 0;
    std::array<long, box_reasons> counts{};
    double seconds = 0;
};

struct CriticalOptions {
    Rational p;
    Rational gap{0};
    int threads = 1;
    int shard = 0, shards = 1;
    int split = 0;                // the start boxes are split_domain(split)
    long max_boxes = 50000000;    // boxes evaluated; the rest become undecided_budget leaves
    double min_width = 1e-10;     // no box narrower than this in every coordinate is split
    double region_radius = 1e-2;  // the first radius tried for a closing region
    // Instead of the whole domain (tests, benchmarks): these boxes, sharded the same way. A result
    // is then about them only, and says so.
    std::vector<ChartBox<DInterval>> start_boxes;
    // > 0: instead, the chart boxes of this half-width around the images of the closing regions,
    // where the bound at gap 0 is decided (InputError when there is no image).
    double around = 0;
    std::function<void(const CriticalProgress&)> progress;  // called about every 2 s from a monitor thread
    // Record each start box's bisection tree in the grammar of the critical-lattice certificate
    // (NOTES.md 12.8) into CriticalResult::trees.
    bool record_trees = false;
};

// A closing region placed in the chart: the chart basis of an image of the optimum is
// W B* P with W in GL(3, Z) (rows: the coefficients of b1, b2, b3 in B*'s basis) and P a signed
// permutation (b_j = sign_j u_(perm_j)), so a chart basis B lies in the region iff
// W^-1 B P^-1 does.
struct ChartImage {
    MinkowskiCase configuration = MinkowskiCase::a3;
    std::array<Coefficients, 3> inverse{};  // W^-1, integral
    std::array<int, 3> perm{};
    std::array<int, 3> sign{};
    DoubleBasis chart_basis{};  // W B* P in floating point (a quick filter)
    std::size_t region = 0;     // index into CriticalResult::regions
};

template <class I>
struct UndecidedBox {
    ChartBox<I> box;
    BoxReason reason = BoxReason::undecided_width;
};

template <class I>
struct CriticalResult {
    Outcome status = Outcome::undecided;  // proved: every box decided, the upper bound holds
    std::string message;
    CriticalReference<I> reference;
    I volume;            // V(K)
    I threshold;         // T: |det| >= T for every lattice packing (when proved)
    I upper_phi;         // V(K) / T
    I relative_gap;      // upper / lower - 1
    std::vector<ClosingRegion<I>> regions;
    std::vector<ChartImage> images;
    std::array<long, box_reasons> counts{};
    long processed = 0;
    long start_boxes = 0;  // top-level boxes of this shard, or the given start boxes
    bool partial_domain = false;  // a shard or given boxes: the bound holds only with the other shards
    std::vector<UndecidedBox<I>> undecided;  // the first few
    double seconds = 0;
    // With CriticalOptions::record_trees and every box decided: this shard's start boxes and the
    // tree of each, in the same order.
    std::vector<ChartBox<I>> boxes;
    std::vector<std::string> trees;
};

// The domain of the command: 1/2 < p <= 10 (p = 1 needs gap > 0), 0 <= gap < 1/2 (InputError).
void require_critical_domain(const Rational& p, const Rational& gap);

CriticalResult<DInterval> critical_bound(const CriticalReference<DInterval>& reference, const CriticalOptions& options);

// What a run fixes before its first box: V(K), the closing regions and their images, T, the
// upper bound and the gap (no boxes, undecided). Deterministic in p and the gap, so --merge
// recomputes it and requires each shard's T to be the same. A gap that puts T below V(K) (above
// 1 - phi of the reference) is an InputError.
CriticalResult<DInterval> critical_setup(const CriticalReference<DInterval>& reference, const CriticalOptions& options);

// One shard's result as `critical --merge` reads it back (its T already matched the setup's).
struct ShardSummary {
    int index = 0, count = 1, split = 0;
    bool proved = false;
    std::array<long, box_reasons> counts{};
    long processed = 0, start_boxes = 0;
    double seconds = 0;
};

// Shards i/n, each i in 0..n-1 exactly once and all at one --split, or an InputError naming one
// missing, repeated, or of another n or split.
void require_shard_cover(const std::vector<ShardSummary>& shards);

// The whole domain's result from shards that pass require_shard_cover: proved iff every shard
// is, with the leaves, boxes and the shards' wall seconds summed.
CriticalResult<DInterval> merge_shards(CriticalResult<DInterval> setup, const std::vector<ShardSummary>& shards);

// The images of a closing region in the chart (exposed for the tests).
std::vector<ChartImage> chart_images(const ClosingRegion<DInterval>& region, std::size_t index);

}  // namespace superpack
