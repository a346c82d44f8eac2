// md's fast event loop (neighbour lists, warm-started and loose GJK; sim/event_md.hpp) against
// the reference loop (every particle's images, full GJK from the centre line), over the same
// short runs with many particles: the same collisions in the same order at the same times, and
// no overlap at the end. Only at first: the loops differ by rounding (the fast loop wraps
// positions into the cell later) and, for superballs, by where in the last contact tolerance
// (1e-10 a R_c) each contact is reported, and the dynamics, chaotic, grows those differences
// until a pair or an order differs (measured: after 681 collisions of the spheres below at
// 1e-9, after 107 and 51 of the superballs at p = 1.5 and 3 at 1e-6).
#include <catch2/catch.hpp>
#include <cmath>

#include "superpack/sim/event_md.hpp"
#include "superpack/sim/periodic_configuration.hpp"
#include "superpack/sim/random_source.hpp"

using namespace superpack::sim;

namespace {

struct Loops {
    EventMdResult reference, fast;
};

Loops both_loops(const SuperballShape& shape, int n, double phi, std::uint64_t seed, double growth, long collisions) {
    RandomSource random(seed);
    const PeriodicConfiguration start = random_configuration(shape, n, phi, random);
    EventMdOptions options;
    options.seed = seed;
    options.growth_rate = growth;
    options.max_collisions = collisions;
    options.collision_log_limit = collisions;
    options.loop = EventLoop::reference;
    Loops loops;
    loops.reference = run_event_md(shape, start, options);
    options.loop = EventLoop::neighbour_lists;
    loops.fast = run_event_md(shape, start, options);
    return loops;
}

// The index of the first collision where the logs differ in the pair or by more than
// `time_tolerance` (relative) in time; the log's size when they agree throughout.
std::size_t first_difference(const EventMdResult& a, const EventMdResult& b, double time_tolerance) {
    const std::size_t size = std::min(a.collision_log.size(), b.collision_log.size());
    for (std::size_t k = 0; k < size; ++k) {
        const CollisionRecord &x = a.collision_log[k], &y = b.collision_log[k];
        if (x.first != y.first || x.second != y.second || std::fabs(x.time - y.time) > time_tolerance * std::fabs(x.time)) return k;
    }
    return size;
}

}  // namespace

TEST_CASE("md's fast loop meets the same collisions as the reference loop: 216 spheres") {
    // Spheres: no GJK, so only the neighbour lists differ, and the times agree to rounding.
    const SuperballShape ball(1);
    const Loops loops = both_loops(ball, 216, 0.3, 21, 0.01, 1000);
    REQUIRE(loops.reference.collision_log.size() == 1000);
    REQUIRE(loops.fast.collision_log.size() == 1000);
    CHECK(first_difference(loops.reference, loops.fast, 1e-9) >= 500);
    CHECK(loops.fast.region_moves > 0);
    CHECK(loops.fast.predictions < loops.reference.predictions);
    CHECK_FALSE(any_overlap(ball, loops.fast.configuration));
}

TEST_CASE("md's fast loop meets the same collisions as the reference loop: 64 superballs at p = 1.5 and 3") {
    for (double p : {1.5, 3.0}) {
        const SuperballShape shape(p);
        const Loops loops = both_loops(shape, 64, 0.3, 22, 0.01, 200);
        INFO("p = " << p << ": reference " << loops.reference.predictions << " predictions, " << loops.reference.advancement_steps
                    << " steps; fast " << loops.fast.predictions << ", " << loops.fast.advancement_steps);
        REQUIRE(loops.reference.collision_log.size() == 200);
        REQUIRE(loops.fast.collision_log.size() == 200);
        CHECK(first_difference(loops.reference, loops.fast, 1e-6) >= 30);
        CHECK(loops.fast.advancement_steps < loops.reference.advancement_steps);
        CHECK_FALSE(any_overlap(shape, loops.fast.configuration));
        CHECK_FALSE(any_overlap(shape, loops.reference.configuration));
    }
}

TEST_CASE("md's fast loop grows 100 superballs to a dense state without overlap, with region moves and cell deformations") {
    const SuperballShape shape(1.5);
    RandomSource random(23);
    const PeriodicConfiguration start = random_configuration(shape, 100, 0.1, random);
    EventMdOptions options;
    options.growth_rate = 0.05;
    options.pressure_limit = 1e3;
    options.cell_moves = 10;
    const EventMdResult result = run_event_md(shape, start, options);
    INFO("phi " << result.phi << ", collisions " << result.collisions << ", region moves " << result.region_moves << ", cell moves kept "
                << result.cell_moves_kept);
    CHECK(result.jammed_pressure);
    CHECK(result.phi > 0.5);
    CHECK(result.region_moves > 100);
    CHECK(result.cell_moves_kept > 0);
    CHECK_FALSE(any_overlap(shape, result.configuration));
    CHECK(result.phi == Approx(density(shape, result.configuration)).epsilon(1e-12));
}
