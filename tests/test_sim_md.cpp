// Event-driven molecular dynamics (sim/event_md.hpp): energy conservation without growth, no
// overlap at the end (at unit scale, the state the proof takes), determinism for a seed, and
// growth that ends larger and still free of overlaps.
#include <catch2/catch.hpp>
#include <cmath>

#include "superpack/sim/event_md.hpp"
#include "superpack/sim/periodic_configuration.hpp"
#include "superpack/sim/random_source.hpp"

using namespace superpack::sim;

namespace {

PeriodicConfiguration dilute_start(const SuperballShape& shape, int n, double phi, std::uint64_t seed) {
    RandomSource random(seed);
    return random_configuration(shape, n, phi, random);
}

bool same_state(const PeriodicConfiguration& a, const PeriodicConfiguration& b) {
    if (a.size() != b.size() || a.cell != b.cell) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Quaternion &q = a.orientations[i], &r = b.orientations[i];
        if (a.fractional[i] != b.fractional[i] || q.w != r.w || q.x != r.x || q.y != r.y || q.z != r.z) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("event-driven MD of 8 spheres at G = 0 conserves energy over thousands of collisions") {
    const SuperballShape shape(1);
    const PeriodicConfiguration start = dilute_start(shape, 8, 0.3, 11);
    EventMdOptions options;
    options.growth_rate = 0;
    options.max_collisions = 5000;
    options.seed = 3;
    long progress_calls = 0;
    const EventMdResult result = run_event_md(shape, start, options, [&](const EventMdProgress&) { ++progress_calls; });
    INFO("a0 " << result.initial_scale << ", phi " << result.phi << ", time " << result.time << ", pressure " << result.pressure
               << ", energy " << result.initial_energy << " -> " << result.final_energy);
    CHECK(result.collision_limit);
    CHECK(result.collisions == 5000);
    CHECK(progress_calls == 5);
    CHECK(result.scale == result.initial_scale);
    CHECK(std::fabs(result.final_energy - result.initial_energy) <= 1e-9 * result.initial_energy);
    CHECK(result.temperature == Approx(1).epsilon(1e-9));
    CHECK(result.pressure > 1);
    CHECK_FALSE(any_overlap(shape, result.configuration));
    CHECK(result.phi == Approx(density(shape, result.configuration)).epsilon(1e-12));

    SECTION("the same seed gives the same end state, another seed another") {
        const EventMdResult again = run_event_md(shape, start, options);
        CHECK(same_state(again.configuration, result.configuration));
        CHECK(again.final_energy == result.final_energy);
        options.seed = 4;
        CHECK_FALSE(same_state(run_event_md(shape, start, options).configuration, result.configuration));
    }
}

TEST_CASE("event-driven MD of rotating superballs at G = 0 conserves translational plus rotational energy") {
    const SuperballShape shape(1.5);
    const PeriodicConfiguration start = dilute_start(shape, 8, 0.3, 12);
    EventMdOptions options;
    options.growth_rate = 0;
    options.max_collisions = 1500;
    const EventMdResult result = run_event_md(shape, start, options);
    INFO("phi " << result.phi << ", predictions " << result.predictions << ", capped " << result.capped_predictions);
    CHECK(result.collisions == 1500);
    CHECK(std::fabs(result.final_energy - result.initial_energy) <= 1e-9 * result.initial_energy);
    CHECK_FALSE(any_overlap(shape, result.configuration));
}

TEST_CASE("event-driven MD with growth ends larger and free of overlaps") {
    for (double p : {1.0, 1.5}) {
        const SuperballShape shape(p);
        const PeriodicConfiguration start = dilute_start(shape, 8, 0.2, 13);
        EventMdOptions options;
        options.growth_rate = 0.05;
        options.max_collisions = p == 1 ? 20000 : 4000;
        options.pressure_limit = 1e5;
        const EventMdResult result = run_event_md(shape, start, options);
        INFO("p = " << p << ": a " << result.initial_scale << " -> " << result.scale << ", phi " << result.phi << ", collisions "
                    << result.collisions << ", pressure " << result.pressure << ", kT " << result.temperature);
        CHECK(result.scale > result.initial_scale * 1.05);
        CHECK(result.rescalings > 0);
        CHECK_FALSE(any_overlap(shape, result.configuration));
        CHECK(result.phi == Approx(density(shape, result.configuration)).epsilon(1e-12));
    }
}

TEST_CASE("largest_free_scale finds the scale of first contact and run_event_md refuses overlapping starts") {
    const SuperballShape ball(1), superball(2);
    // Two particles on the diagonal of a cubic cell of side 4: spheres touch at half the distance.
    PeriodicConfiguration pair;
    pair.cell = {Vector3{4, 0, 0}, Vector3{0, 4, 0}, Vector3{0, 0, 4}};
    pair.fractional = {{0, 0, 0}, {0.25, 0, 0}};
    pair.orientations = {Quaternion{}, Quaternion{}};
    CHECK(largest_free_scale(ball, pair) == Approx(0.5).epsilon(1e-12));
    // Unrotated superballs along e_1 touch face to face, also at half the distance.
    CHECK(largest_free_scale(superball, pair) == Approx(0.5).epsilon(1e-10));
    EventMdOptions options;
    options.initial_scale = 0.6;
    CHECK_THROWS_AS(run_event_md(ball, pair, options), std::invalid_argument);
}

TEST_CASE("event-driven MD in a deforming cell changes the cell's shape at fixed volume and ends free of overlaps") {
    const SuperballShape shape(2);
    // Cube-aligned FCC, 8 bodies, grown from 0.9 of their largest free scale.
    const PeriodicConfiguration start = lattice_configuration({Vector3{1, 1, 0}, Vector3{1, 0, 1}, Vector3{0, 1, 1}}, 8, 1);
    EventMdOptions options;
    options.growth_rate = 0.05;
    options.initial_scale = 0.9 * largest_free_scale(shape, start);
    options.max_collisions = 3000;
    options.cell_moves = 10;
    const EventMdResult result = run_event_md(shape, start, options);
    INFO("a " << result.initial_scale << " -> " << result.scale << ", phi " << result.phi << ", cell moves kept "
              << result.cell_moves_kept);
    CHECK(result.cell_moves_kept > 0);
    CHECK_FALSE(same_state(result.configuration, start));
    // The end state is at unit scale: its cell times a has the start's volume.
    const double volume = std::fabs(determinant(result.configuration.cell)) * std::pow(result.scale, 3);
    CHECK(volume == Approx(std::fabs(determinant(start.cell))).epsilon(1e-9));
    Matrix3 scaled = result.configuration.cell;
    for (Vector3& row : scaled) row = result.scale * row;
    CHECK(scaled != start.cell);  // the shape moved
    CHECK_FALSE(any_overlap(shape, result.configuration));
    CHECK(result.phi == Approx(density(shape, result.configuration)).epsilon(1e-12));
}
