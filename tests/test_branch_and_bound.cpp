// The branch-and-bound engine of solve/ on a driver whose tree is known exactly: the dyadic
// intervals of [0, 1) with integer ends in units of 2^-depth, split down to a fixed depth or
// until they hold no multiple of 1/3 (the leaves are then "free"; the others at the floor
// "hit"). Every number here is exact, so the tests compare counts, orders and trees.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <thread>

#include "superpack/solve/branch_and_bound.hpp"
#include "support.hpp"

using namespace superpack;

namespace {

struct Dyadic {
    long lo = 0, hi = 1;  // [lo, hi) * 2^-depth
    int depth = 0;
    bool filed = false;   // DeferringDriver: deferred once already
};

enum Reason : std::size_t { free_of_thirds, holds_a_third, left_open };

struct Leaf {
    Dyadic box;
    Reason reason;
};

// Does [lo, hi) 2^-depth hold k/3 for an integer k, i.e. is there k with 3 lo <= k 2^depth < 3 hi?
bool holds_third(const Dyadic& box) {
    const long scale = 1L << box.depth;
    const long first = (3 * box.lo + scale - 1) / scale;  // the least k with k 2^depth >= 3 lo
    return first * scale < 3 * box.hi;
}

struct ThirdsDriver {
    using Box = Dyadic;
    using Leaf = ::Leaf;
    int floor = 6;
    std::vector<Leaf> leaves;
    long stop_at_lo = -1;  // a free leaf starting here stops the run (at the floor depth)
    std::atomic<int>* wait_for_progress = nullptr;  // the first box waits (up to 10 s) for a progress line
    long throw_at_lo = -1;  // examining the floor interval starting here throws

    Examined<Box, Leaf> examine(const Box& box, Visit& visit) const {
        for (int waited = 0; wait_for_progress && *wait_for_progress == 0 && waited < 10000; ++waited)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        if (box.depth == floor && box.lo == throw_at_lo) throw std::runtime_error("the driver failed");
        if (!holds_third(box)) {
            if (visit.letters) *visit.letters += 'F';
            const bool stop = box.depth == floor && box.lo == stop_at_lo;
            return leaf_of<Box>(Leaf{box, free_of_thirds}, stop);
        }
        if (box.depth == floor) {
            if (visit.letters) *visit.letters += 'H';
            return leaf_of<Box>(Leaf{box, holds_a_third});
        }
        if (visit.letters) *visit.letters += 'S';
        return split_of<Box, Leaf>(box);
    }
    std::array<Box, 2> split(const Box& box) const {
        return {Dyadic{2 * box.lo, 2 * box.lo + 1, box.depth + 1}, Dyadic{2 * box.lo + 1, 2 * box.hi, box.depth + 1}};
    }
    Leaf unexamined(const Box& box) const { return Leaf{box, left_open}; }
    std::size_t reason(const Leaf& leaf) const { return leaf.reason; }
    void collect(Leaf&& leaf) { leaves.push_back(leaf); }
    double priority(const Box& box) const { return -static_cast<double>(box.lo) / static_cast<double>(1L << box.depth); }
};

// The leaves' left ends as fractions of 2^floor.
std::vector<long> left_ends(const std::vector<Leaf>& leaves, int floor) {
    std::vector<long> ends;
    for (const Leaf& leaf : leaves) ends.push_back(leaf.box.lo << (floor - leaf.box.depth));
    return ends;
}

}  // namespace

TEST_CASE("branch and bound: depth first closes a 1-D domain's leaves left to right, and covers it") {
    ThirdsDriver driver;
    const BranchResult<Dyadic> result = branch_and_bound(driver, {Dyadic{}}, BranchOptions{});
    const std::vector<long> ends = left_ends(driver.leaves, driver.floor);
    CHECK(std::is_sorted(ends.begin(), ends.end()));
    // The leaves tile [0, 1): each starts where the one before ends.
    long reach = 0;
    for (const Leaf& leaf : driver.leaves) {
        CHECK((leaf.box.lo << (driver.floor - leaf.box.depth)) == reach);
        reach = leaf.box.hi << (driver.floor - leaf.box.depth);
    }
    CHECK(reach == 64);
    // 0, 1/3 and 2/3 each lie in one floor interval ([21, 22) and [42, 43) in 64ths): three hit leaves.
    REQUIRE(result.counts.size() >= 2);
    CHECK(result.counts[holds_a_third] == 3);
    CHECK(result.counts[free_of_thirds] + result.counts[holds_a_third] == static_cast<long>(driver.leaves.size()));
    // A full binary tree: splits = leaves - 1, and every box taken was examined.
    CHECK(result.processed == 2 * static_cast<long>(driver.leaves.size()) - 1);
    CHECK(result.examined == result.processed);
    CHECK(!result.stopped);
}

TEST_CASE("branch and bound: best first takes the least priority first") {
    ThirdsDriver driver;
    BranchOptions options;
    options.order = BranchOrder::best_first;
    branch_and_bound(driver, {Dyadic{}}, options);
    // The priority is minus the left end, so the leaves close from right to left.
    const std::vector<long> ends = left_ends(driver.leaves, driver.floor);
    CHECK(std::is_sorted(ends.rbegin(), ends.rend()));
    CHECK(ends.front() > ends.back());
}

TEST_CASE("branch and bound: a budget leaves the boxes still queued unexamined, none dropped") {
    ThirdsDriver full;
    const long all = branch_and_bound(full, {Dyadic{}}, BranchOptions{}).processed;
    for (const long budget : {1L, 5L, 20L}) {
        ThirdsDriver driver;
        BranchOptions options;
        options.max_boxes = budget;
        const BranchResult<Dyadic> result = branch_and_bound(driver, {Dyadic{}}, options);
        INFO("budget " << budget);
        CHECK(result.examined == budget);
        CHECK(result.processed < all);
        REQUIRE(result.counts.size() == 3);
        CHECK(result.counts[left_open] > 0);
        // What was decided and what was left open still tile [0, 1).
        long length = 0;
        for (const Leaf& leaf : driver.leaves) length += (leaf.box.hi - leaf.box.lo) << (driver.floor - leaf.box.depth);
        CHECK(length == 64);
    }
}

// A driver with only what a run without a budget needs: one reason (single_reason: every leaf
// counts as 0) and no leaves for unexamined boxes.
struct MinimalDriver {
    using Box = Dyadic;
    using Leaf = ::Leaf;
    static constexpr bool single_reason = true;
    std::vector<Leaf> leaves;
    Examined<Box, Leaf> examine(const Box& box, Visit&) const {
        if (box.depth == 3) return leaf_of<Box>(Leaf{box, holds_a_third});
        return split_of<Box, Leaf>(box);
    }
    std::array<Box, 2> split(const Box& box) const {
        return {Dyadic{2 * box.lo, 2 * box.lo + 1, box.depth + 1}, Dyadic{2 * box.lo + 1, 2 * box.hi, box.depth + 1}};
    }
    void collect(Leaf&& leaf) { leaves.push_back(leaf); }
};

TEST_CASE("branch and bound: a driver without reasons counts its leaves as 0, and one without unexamined refuses a budget") {
    MinimalDriver driver;
    const BranchResult<Dyadic> result = branch_and_bound(driver, {Dyadic{}}, BranchOptions{});
    REQUIRE(result.counts.size() == 1);
    CHECK(result.counts[0] == 8);
    CHECK(driver.leaves.size() == 8);
    MinimalDriver budgeted;
    BranchOptions options;
    options.max_boxes = 3;
    CHECK_THROWS_AS(branch_and_bound(budgeted, {Dyadic{}}, options), std::logic_error);
}

TEST_CASE("branch and bound: a leaf that answers the run drops the rest") {
    ThirdsDriver driver;
    driver.stop_at_lo = 43;  // the free floor interval [43, 44) of 64ths, beside 2/3's [42, 43)
    const BranchResult<Dyadic> result = branch_and_bound(driver, {Dyadic{}}, BranchOptions{});
    CHECK(result.stopped);
    CHECK(result.counts.size() < 3);  // no leaf left unexamined
    CHECK(result.examined == result.processed);
    // Depth first, everything left of the stopping leaf was decided before it, and it came last.
    REQUIRE(!driver.leaves.empty());
    CHECK(driver.leaves.back().box.lo == 43);
    long reach = 0;
    for (const Leaf& leaf : driver.leaves) {
        CHECK((leaf.box.lo << (driver.floor - leaf.box.depth)) == reach);
        reach = leaf.box.hi << (driver.floor - leaf.box.depth);
    }
    CHECK(reach == 44);
}

namespace {

// New boxes are deferred into best-first order by their left end (so the leaves still close
// from left to right), and a box taken back is decided as ThirdsDriver does; from `stop_from`
// (in 64ths) on, a box taken back stops the run instead.
struct DeferringDriver : ThirdsDriver {
    long stop_from = -1;
    std::vector<Visit> visits;

    Examined<Box, Leaf> examine(const Box& box, Visit& visit) {
        visits.push_back(visit);
        const long left = box.lo << (floor - box.depth);
        if (!box.filed) {
            Dyadic filed = box;
            filed.filed = true;
            return defer_of<Box, Leaf>(filed, static_cast<double>(left));
        }
        if (stop_from >= 0 && left >= stop_from) return stop_at<Box, Leaf>(box);
        return ThirdsDriver::examine(box, visit);
    }
};

}  // namespace

TEST_CASE("branch and bound: deferred boxes are taken by priority after the stack, with exact visit counts") {
    DeferringDriver driver;
    const BranchResult<Dyadic> result = branch_and_bound(driver, {Dyadic{}}, BranchOptions{});
    CHECK(!result.stopped);
    REQUIRE(result.counts.size() >= 2);
    CHECK(result.counts[holds_a_third] == 3);
    long reach = 0;
    for (const Leaf& leaf : driver.leaves) {
        CHECK((leaf.box.lo << (driver.floor - leaf.box.depth)) == reach);
        reach = leaf.box.hi << (driver.floor - leaf.box.depth);
    }
    CHECK(reach == 64);
    // The root new, then taken back; its children new (the second waits on the stack), then
    // both deferred and the first taken back.
    REQUIRE(driver.visits.size() >= 5);
    const long expected[5][3] = {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 1, 1}};
    for (int k = 0; k < 5; ++k) {
        INFO("visit " << k);
        CHECK(driver.visits[k].closed_leaves == expected[k][0]);
        CHECK(driver.visits[k].queued == expected[k][1]);
        CHECK(driver.visits[k].deferred == expected[k][2]);
    }
}

TEST_CASE("branch and bound: stopping at a box leaves it and the rest unexamined, it first") {
    DeferringDriver driver;
    driver.stop_from = 32;
    const BranchResult<Dyadic> result = branch_and_bound(driver, {Dyadic{}}, BranchOptions{});
    CHECK(result.stopped);
    REQUIRE(result.counts.size() == 3);
    CHECK(result.counts[left_open] >= 1);
    const auto first_left = std::find_if(driver.leaves.begin(), driver.leaves.end(),
                                         [](const Leaf& leaf) { return leaf.reason == left_open; });
    REQUIRE(first_left != driver.leaves.end());
    CHECK(first_left->box.lo == 1);
    CHECK(first_left->box.depth == 1);  // [1/2, 1), the box taken back
    long length = 0;
    for (const Leaf& leaf : driver.leaves) length += (leaf.box.hi - leaf.box.lo) << (driver.floor - leaf.box.depth);
    CHECK(length == 64);
}

TEST_CASE("branch and bound: a driver's exception ends the run and reaches the caller on any number of threads") {
    for (const int threads : {1, 2}) {
        ThirdsDriver driver;
        driver.throw_at_lo = 21;  // 1/3's floor interval
        BranchOptions options;
        options.threads = threads;
        options.progress = [](const BranchProgress&) {};
        INFO("threads " << threads);
        CHECK_THROWS_AS(branch_and_bound(driver, {Dyadic{}}, options), std::runtime_error);
    }
}

TEST_CASE("branch and bound: shards take the start boxes i mod n, and together cover them once") {
    const std::vector<Dyadic> start = split_start_boxes(std::vector<Dyadic>{Dyadic{}}, 3, [](const Dyadic& box) {
        return ThirdsDriver{}.split(box);
    });
    REQUIRE(start.size() == 8);
    for (std::size_t k = 0; k < start.size(); ++k) CHECK(start[k].lo == static_cast<long>(k));  // in order
    ThirdsDriver whole;
    const BranchResult<Dyadic> all = branch_and_bound(whole, start, BranchOptions{});
    std::multiset<long> leaves;
    long processed = 0;
    for (int shard = 0; shard < 3; ++shard) {
        ThirdsDriver driver;
        BranchOptions options;
        options.shard = shard;
        options.shards = 3;
        const BranchResult<Dyadic> result = branch_and_bound(driver, start, options);
        for (std::size_t k = 0; k < result.starts.size(); ++k) CHECK(result.starts[k].lo % 3 == shard);
        for (const long end : left_ends(driver.leaves, driver.floor)) leaves.insert(end);
        processed += result.processed;
    }
    const std::vector<long> expected = left_ends(whole.leaves, whole.floor);
    CHECK(std::vector<long>(leaves.begin(), leaves.end()) == expected);
    CHECK(processed == all.processed);
}

TEST_CASE("branch and bound: threads give the same leaves and trees as one thread") {
    const std::vector<Dyadic> start = split_start_boxes(std::vector<Dyadic>{Dyadic{}}, 2, [](const Dyadic& box) {
        return ThirdsDriver{}.split(box);
    });
    BranchOptions options;
    options.record_trees = true;
    ThirdsDriver one;
    one.floor = 12;
    const BranchResult<Dyadic> single = branch_and_bound(one, start, options);
    // Pre-order of the first start box [0, 1/4): split down to the floor along 0 (the left
    // edge), every right child free; a left-edge floor leaf holds 0.
    CHECK(single.trees.at(0) == std::string(10, 'S').insert(10, "H") + std::string(10, 'F'));
    options.threads = 2;
    ThirdsDriver two;
    two.floor = 12;
    const BranchResult<Dyadic> parallel = branch_and_bound(two, start, options);
    CHECK(parallel.trees == single.trees);
    CHECK(parallel.counts == single.counts);
    CHECK(parallel.processed == single.processed);
    std::vector<long> a = left_ends(one.leaves, 12), b = left_ends(two.leaves, 12);
    std::sort(b.begin(), b.end());
    CHECK(a == b);
}

TEST_CASE("branch and bound: progress is reported from a monitor thread") {
    ThirdsDriver driver;
    std::atomic<int> calls{0};
    driver.wait_for_progress = &calls;
    BranchOptions options;
    options.progress_interval = std::chrono::milliseconds(5);
    std::atomic<long> seen{0};  // the most boxes a progress line saw (no assertion off the main thread)
    options.progress = [&](const BranchProgress& progress) {
        seen = std::max(seen.load(), progress.processed);
        ++calls;
    };
    const long processed = branch_and_bound(driver, {Dyadic{}}, options).processed;
    CHECK(calls > 0);
    CHECK(seen > 0);
    CHECK(seen <= processed);
}
