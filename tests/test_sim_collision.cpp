// Collisions of moving, rotating, growing superballs (sim/collision.hpp): the conservative-
// advancement predictor against brute-force time stepping (it must never report a contact later
// than the first overlap that small time steps see, nor miss one), the elastic response's
// conservation laws and DTS's growth correction, and the inertia factor k(p) against its closed
// form.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "superpack/sim/collision.hpp"
#include "superpack/sim/overlap.hpp"
#include "superpack/sim/random_source.hpp"

using namespace superpack::sim;

namespace {

const std::vector<double> exponents{0.5, 0.6, 1, 1.5, 2, 3, 10};

// k(p) = 2 <x_1^2> = 2 Gamma(3/q) Gamma(1 + 3/q) / (Gamma(1/q) Gamma(1 + 5/q)), q = 2p, from
// the Dirichlet integrals over K's positive octant.
double closed_form_inertia_factor(double p) {
    const double q = 2 * p;
    return 2 * std::exp(std::lgamma(3 / q) + std::lgamma(1 + 3 / q) - std::lgamma(1 / q) - std::lgamma(1 + 5 / q));
}

// A body's unit-scale placement at time t (the trick dist_a(c_i, c_j) = a dist_1(c_i/a, c_j/a)).
Placement unit_placement(const MovingBody& body, double t, double scale) {
    const MovingBody moved = advance(body, t);
    return {(1 / scale) * moved.center, rotation_matrix(moved.orientation)};
}

// A random pair at scale a0, apart, b moving roughly towards a (so that most pairs collide,
// some graze, some miss), both spinning.
struct Pair {
    MovingBody a, b;
    double a0, G;
};

Pair random_pair(const SuperballShape& shape, RandomSource& random) {
    Pair pair;
    pair.a0 = random.uniform(0.5, 1.5);
    pair.G = random.uniform() < 0.3 ? 0.0 : random.uniform(0, 0.5);
    const double radius = shape.circumradius();
    for (;;) {
        const Vector3 direction = random.unit_vector();
        // Half the starts with the bounding spheres apart, half closer (inside 2 a R_c).
        const double reach = random.uniform() < 0.5 ? random.uniform(1.0, 1.8) : random.uniform(0.8, 1.0);
        pair.a = {{0, 0, 0}, random.rotation(), random.cube_point(0.5), random.cube_point(3)};
        pair.b = {(2 * radius * pair.a0 * reach) * direction, random.rotation(), {0, 0, 0}, random.cube_point(3)};
        pair.b.velocity = pair.a.velocity - random.uniform(0.5, 2.0) * (direction + 0.6 * random.unit_vector());
        const Separation start = separation(shape, unit_placement(pair.a, 0, pair.a0), unit_placement(pair.b, 0, pair.a0));
        if (!start.overlapping && start.distance > 1e-3) return pair;
    }
}

double rigid_normal_velocity(const MovingBody& a, const MovingBody& b, const Contact& contact) {
    const Vector3 xa = contact.point - a.center, xb = contact.point - b.center;
    return dot(contact.normal, (b.velocity + cross(b.angular_velocity, xb)) - (a.velocity + cross(a.angular_velocity, xa)));
}

}  // namespace

TEST_CASE("the contact predictor never reports a contact later than brute-force time stepping sees one") {
    RandomSource random(20240516);
    const double horizon = 2.0;
    const int steps = 4000;
    int pairs = 0, contacts = 0, brute_force_overlaps = 0, capped = 0;
    // The distance over a R_c at the predicted contacts: between the margin (a quarter of the
    // tolerance 1e-10) and the tolerance, up to GJK's accuracy.
    double largest_contact_gap = 0, smallest_contact_gap = 1;
    for (double p : exponents) {
        const SuperballShape shape(p);
        for (int trial = 0; trial < 110; ++trial) {
            const Pair pair = random_pair(shape, random);
            const ContactPrediction prediction = first_contact(shape, pair.a, pair.b, pair.a0, pair.G, horizon);
            ++pairs;
            capped += prediction.outcome == ContactOutcome::capped;
            // The first sampled time at which the bodies overlap.
            double first_overlap = -1;
            for (int step = 0; step <= steps; ++step) {
                const double t = horizon * step / steps;
                const double scale = pair.a0 + pair.G * t;
                if (overlapping(shape, unit_placement(pair.a, t, scale), unit_placement(pair.b, t, scale))) {
                    first_overlap = t;
                    break;
                }
            }
            INFO("p = " << p << ", trial " << trial << ", predicted " << prediction.time << " (outcome "
                        << static_cast<int>(prediction.outcome) << "), first overlap " << first_overlap);
            if (first_overlap >= 0) {
                ++brute_force_overlaps;
                // Not missed, and not late: so no sampled time before the prediction overlaps.
                REQUIRE(prediction.outcome != ContactOutcome::none);
                REQUIRE(prediction.time <= first_overlap);
            }
            if (prediction.outcome == ContactOutcome::contact) {
                ++contacts;
                // A real contact: the bodies are apart there, by at most about the tolerance.
                const double scale = pair.a0 + pair.G * prediction.time;
                const Separation at = separation(shape, unit_placement(pair.a, prediction.time, scale), unit_placement(pair.b, prediction.time, scale));
                REQUIRE_FALSE(at.overlapping);
                largest_contact_gap = std::max(largest_contact_gap, at.distance / shape.circumradius());
                smallest_contact_gap = std::min(smallest_contact_gap, at.distance / shape.circumradius());
                REQUIRE(at.distance <= 1e-9 * shape.circumradius());
            }
        }
    }
    INFO("contact gaps " << smallest_contact_gap << " to " << largest_contact_gap << "; " << pairs << " pairs, " << contacts << " contacts, " << brute_force_overlaps << " seen by brute force, " << capped << " capped");
    CHECK(pairs == 770);
    CHECK(brute_force_overlaps > 300);
    // Grazing pairs may hit the Zeno cap (2000 steps): its time is still a lower bound (checked
    // above), and the event loop predicts again from there. Rare: 2 of 770 here.
    CHECK(capped <= 8);
    CHECK(largest_contact_gap <= 1.01e-10);
    CHECK(smallest_contact_gap >= 2.4e-11);
}

TEST_CASE("the predictor reports no contact for receding bodies and for a pair just after a collision") {
    for (double p : exponents) {
        const SuperballShape shape(p);
        RandomSource random(7);
        // Two bodies approaching head-on along e_1 with spin, G = 0.1.
        const MovingBody a{{0, 0, 0}, random.rotation(), {0.5, 0, 0}, random.cube_point(1)};
        const MovingBody b{{3 * shape.circumradius(), 0.1, 0}, random.rotation(), {-0.5, 0, 0}, random.cube_point(1)};
        const double a0 = 1, G = 0.1;
        const ContactPrediction hit = first_contact(shape, a, b, a0, G, 10);
        REQUIRE(hit.outcome == ContactOutcome::contact);
        MovingBody a_hit = advance(a, hit.time), b_hit = advance(b, hit.time);
        const double scale = a0 + G * hit.time;
        const Contact touching = contact(shape, a_hit, b_hit, scale);
        REQUIRE(normal_gap_rate(a_hit, b_hit, scale, G, touching) < 0);
        collide(inertia_factor(p), scale, G, touching, a_hit, b_hit);
        REQUIRE(normal_gap_rate(a_hit, b_hit, scale, G, touching) > 0);
        // Within the tolerance but opening: the predictor steps on rather than report it again.
        // At p = 1/2 (an octahedron, whose contacts are edges and faces) the impulse at one
        // point may leave another closing: then a few more collisions at once, as the event
        // loop would take them, until the pair opens.
        ContactPrediction again = first_contact(shape, a_hit, b_hit, scale, G, 0.5);
        int repeats = 0;
        while (p == 0.5 && again.outcome == ContactOutcome::contact && again.time < 1e-6 && repeats < 20) {
            a_hit = advance(a_hit, again.time);
            b_hit = advance(b_hit, again.time);
            const double later = scale + G * again.time;
            collide(inertia_factor(p), later, G, contact(shape, a_hit, b_hit, later), a_hit, b_hit);
            again = first_contact(shape, a_hit, b_hit, later, G, 0.5);
            ++repeats;
        }
        INFO("p = " << p << ", again at " << again.time << " outcome " << static_cast<int>(again.outcome) << " after " << repeats << " repeats");
        CHECK(repeats < 20);
        CHECK(!(again.outcome == ContactOutcome::contact && again.time < 1e-6));
    }
}

TEST_CASE("the elastic response conserves energy and momenta at G = 0 and reverses the normal velocity") {
    RandomSource random(99);
    for (double p : exponents) {
        const SuperballShape shape(p);
        const double k = inertia_factor(p);
        int collisions = 0;
        for (int trial = 0; trial < 40 && collisions < 20; ++trial) {
            Pair pair = random_pair(shape, random);
            pair.G = 0;
            const ContactPrediction hit = first_contact(shape, pair.a, pair.b, pair.a0, 0, 2.0);
            if (hit.outcome != ContactOutcome::contact) continue;
            ++collisions;
            MovingBody a = advance(pair.a, hit.time), b = advance(pair.b, hit.time);
            const double scale = pair.a0, inertia = k * scale * scale;
            const Contact touching = contact(shape, a, b, scale);
            const auto energy = [&] {
                return 0.5 * (dot(a.velocity, a.velocity) + dot(b.velocity, b.velocity)) +
                       0.5 * inertia * (dot(a.angular_velocity, a.angular_velocity) + dot(b.angular_velocity, b.angular_velocity));
            };
            const auto momentum = [&] { return a.velocity + b.velocity; };
            // About the origin: orbital plus spin, I omega with the isotropic inertia.
            const auto angular_momentum = [&] {
                return cross(a.center, a.velocity) + cross(b.center, b.velocity) + inertia * (a.angular_velocity + b.angular_velocity);
            };
            const double energy_before = energy(), normal_before = rigid_normal_velocity(a, b, touching);
            const Vector3 momentum_before = momentum(), angular_before = angular_momentum();
            REQUIRE(normal_before < 0);
            const CollisionResponse response = collide(k, scale, 0, touching, a, b);
            INFO("p = " << p << ", trial " << trial);
            CHECK(response.impulse > 0);
            CHECK(std::fabs(energy() - energy_before) <= 1e-13 * energy_before);
            CHECK(std::fabs(response.energy_change) <= 1e-13 * energy_before);
            CHECK(norm(momentum() - momentum_before) <= 1e-13 * (1 + norm(momentum_before)));
            CHECK(norm(angular_momentum() - angular_before) <= 1e-12 * (1 + norm(angular_before)));
            CHECK(rigid_normal_velocity(a, b, touching) == Approx(-normal_before).epsilon(1e-12));
            // Spheres: the impulse passes through the centres, the spins do not change.
            if (p == 1) CHECK(norm(a.angular_velocity - advance(pair.a, hit.time).angular_velocity) <= 1e-14);
        }
        CHECK(collisions == 20);
    }
}

TEST_CASE("with growth the response reverses the closing rate, separates at least at the growth rate and injects energy") {
    RandomSource random(5);
    for (double p : exponents) {
        const SuperballShape shape(p);
        const double k = inertia_factor(p);
        int collisions = 0;
        for (int trial = 0; trial < 60 && collisions < 10; ++trial) {
            Pair pair = random_pair(shape, random);
            pair.G = random.uniform(0.05, 0.5);
            const ContactPrediction hit = first_contact(shape, pair.a, pair.b, pair.a0, pair.G, 2.0);
            if (hit.outcome != ContactOutcome::contact) continue;
            ++collisions;
            MovingBody a = advance(pair.a, hit.time), b = advance(pair.b, hit.time);
            const double scale = pair.a0 + pair.G * hit.time;
            const Contact touching = contact(shape, a, b, scale);
            const double closing = normal_gap_rate(a, b, scale, pair.G, touching);
            const double growth = (pair.G / scale) * (dot(touching.normal, touching.point - a.center) - dot(touching.normal, touching.point - b.center));
            REQUIRE(closing < 0);
            const CollisionResponse response = collide(k, scale, pair.G, touching, a, b);
            INFO("p = " << p << ", trial " << trial);
            CHECK(normal_gap_rate(a, b, scale, pair.G, touching) == Approx(-closing).epsilon(1e-12));
            CHECK(rigid_normal_velocity(a, b, touching) >= growth);
            CHECK(response.energy_change > 0);
        }
        CHECK(collisions == 10);
    }
}

TEST_CASE("the inertia factor k(p) = <x1^2 + x2^2> over K by quadrature") {
    CHECK(std::fabs(inertia_factor(1) - 0.4) <= 1e-6);
    CHECK(std::fabs(inertia_factor(1) - 0.4) <= 1e-13);
    CHECK(std::fabs(inertia_factor(0.5) - 0.2) <= 1e-12);  // the octahedron: 2 * 2! 3! / 5!
    // The cube limit [-1, 1]^3: <x1^2 + x2^2> = 2/3.
    CHECK(std::fabs(inertia_factor(1e6) - 2.0 / 3) <= 1e-5);
    for (double p : {0.5, 0.6, 0.75, 1.0, 1.5, 2.0, 3.0, 10.0, 100.0, 1e4}) {
        INFO("p = " << p);
        CHECK(std::fabs(inertia_factor(p) - closed_form_inertia_factor(p)) <= 1e-11);
    }
    // Cached: the same value again.
    CHECK(inertia_factor(1.5) == inertia_factor(1.5));
}
