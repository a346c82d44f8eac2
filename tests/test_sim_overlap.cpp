// The simulation's floating-point geometry (sim/): vectors and rotations, the superball's
// support map, and GJK's overlap and distance tests, against closed forms at contact and
// against brute force over dense samples of the bodies' boundaries and of directions.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "superpack/sim/overlap.hpp"
#include "superpack/sim/quaternion.hpp"
#include "superpack/sim/superball_shape.hpp"
#include "superpack/sim/vector3.hpp"

using namespace superpack::sim;

namespace {

// The p where the support map changes character: the octahedron, just above it (exponents of
// 5 10^6), the ball, smooth superballs, and near-cubes up to p = 10^6.
const std::vector<double> shape_exponents{0.5, 0.5000001, 1, 2, 3, 50, 1e3, 1e6};

// The test's own randomness, so that a failure reproduces on every standard library.
class Random {
public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
    Vector3 unit_vector() {
        for (;;) {
            const Vector3 x{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
            const double length = norm(x);
            if (length > 0.1 && length <= 1) return (1 / length) * x;
        }
    }
    Matrix3 rotation() {
        const Vector3 axis = unit_vector();
        return rotation_matrix(Quaternion{uniform(-1, 1), axis[0], axis[1], axis[2]});
    }

private:
    std::mt19937_64 engine_;
};

// n nearly evenly spread unit vectors (the Fibonacci sphere).
std::vector<Vector3> sphere_points(int n) {
    std::vector<Vector3> points;
    const double golden_angle = M_PI * (3 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1 - (2 * i + 1.0) / n, radius = std::sqrt(1 - z * z);
        points.push_back({radius * std::cos(golden_angle * i), radius * std::sin(golden_angle * i), z});
    }
    return points;
}

// Points of the boundary of a placed body: the sphere's points pushed radially onto bd K.
std::vector<Vector3> boundary_samples(const SuperballShape& shape, const Placement& body, int n) {
    std::vector<Vector3> samples;
    for (const Vector3& u : sphere_points(n)) samples.push_back(body.center + apply(body.rotation, (1 / shape.gauge(u)) * u));
    return samples;
}

// The gap that the plane with unit normal n (from a towards b) leaves between the bodies.
double plane_gap(const SuperballShape& shape, const Placement& a, const Placement& b, const Vector3& n) {
    return -support_value(shape, b, -n) - support_value(shape, a, n);
}

// The distance of disjoint convex bodies is the largest such gap over all n (and a nonpositive
// largest gap means they meet): the best of dense directions, then refined by a shrinking
// random search. A lower bound on the distance, close to it.
double brute_force_largest_gap(const SuperballShape& shape, const Placement& a, const Placement& b, Random& random) {
    Vector3 best_direction{1, 0, 0};
    double best = -std::numeric_limits<double>::infinity();
    for (const Vector3& n : sphere_points(3000)) {
        const double gap = plane_gap(shape, a, b, n);
        if (gap > best) best = gap, best_direction = n;
    }
    for (double step = 0.05; step > 1e-10; step *= 0.85)
        for (int trial = 0; trial < 30; ++trial) {
            const Vector3 moved = best_direction + step * random.unit_vector();
            const Vector3 n = (1 / norm(moved)) * moved;
            const double gap = plane_gap(shape, a, b, n);
            if (gap > best) best = gap, best_direction = n;
        }
    return best;
}

double max_entry_difference(const Matrix3& x, const Matrix3& y) {
    double result = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) result = std::max(result, std::fabs(x[i][j] - y[i][j]));
    return result;
}

Placement at(const Vector3& center, const Matrix3& rotation = identity_matrix()) { return {center, rotation}; }

detail::GjkTrace trace_of(const SuperballShape& shape, const Placement& a, const Placement& b) {
    detail::GjkTrace trace;
    detail::gjk(shape, a, b, false, &trace);
    return trace;
}

}  // namespace

TEST_CASE("vectors, matrices and quaternions") {
    const Matrix3 m{Vector3{2, 1, 0}, Vector3{-1, 3, 1}, Vector3{0.5, 0, 4}};
    CHECK(determinant(m) == Approx(2 * 12 - 1 * (-4 - 0.5)));
    CHECK(max_entry_difference(multiply(m, inverse(m)), identity_matrix()) < 1e-15);
    CHECK(apply(m, Vector3{1, 2, 3}) == Vector3{4, 8, 12.5});
    CHECK(apply_transpose(m, Vector3{1, 2, 3}) == Vector3{1.5, 7, 14});
    CHECK(row_combination(m, Vector3{1, 2, 3}) == apply(transpose(m), Vector3{1, 2, 3}));
    CHECK(cross(Vector3{1, 0, 0}, Vector3{0, 1, 0}) == Vector3{0, 0, 1});
    CHECK_THROWS_AS(inverse(Matrix3{Vector3{1, 2, 3}, Vector3{2, 4, 6}, Vector3{0, 0, 1}}), std::invalid_argument);

    // axis_angle is right-handed; rotation_matrix maps body to space coordinates.
    const Matrix3 quarter = rotation_matrix(axis_angle({0, 0, 1}, M_PI / 2));
    CHECK(norm(apply(quarter, Vector3{1, 0, 0}) - Vector3{0, 1, 0}) < 1e-15);
    // A product of quaternions is the product of their rotations, and any nonzero multiple of
    // a quaternion gives the same rotation.
    const Quaternion q = normalized(Quaternion{0.3, -1, 2, 0.5}), s = normalized(Quaternion{-2, 0.1, 0.7, 1});
    CHECK(max_entry_difference(rotation_matrix(multiply(q, s)), multiply(rotation_matrix(q), rotation_matrix(s))) < 1e-15);
    CHECK(max_entry_difference(rotation_matrix(Quaternion{0.3e-200, -1e-200, 2e-200, 0.5e-200}), rotation_matrix(q)) < 1e-15);
    const Matrix3 r = rotation_matrix(Quaternion{7, -3, 2, 11});
    CHECK(max_entry_difference(multiply(r, transpose(r)), identity_matrix()) < 1e-15);
    CHECK(determinant(r) == Approx(1).epsilon(1e-15));
    CHECK_THROWS_AS(rotation_matrix(Quaternion{0, 0, 0, 0}), std::invalid_argument);
    CHECK_THROWS_AS(normalized(Quaternion{0, 0, 0, 0}), std::invalid_argument);
}

TEST_CASE("the superball's domain and circumradius") {
    CHECK_THROWS_AS(SuperballShape(0.4999999), std::invalid_argument);
    CHECK_THROWS_AS(SuperballShape(std::nan("")), std::invalid_argument);
    CHECK_THROWS_AS(SuperballShape(std::numeric_limits<double>::infinity()), std::invalid_argument);
    CHECK(SuperballShape(0.5).circumradius() == 1);
    CHECK(SuperballShape(1).circumradius() == 1);
    CHECK(SuperballShape(1e6).circumradius() == Approx(std::sqrt(3.0)).epsilon(1e-5));
    // The circumradius is the largest |x| on the boundary: attained, and never exceeded.
    for (double p : shape_exponents) {
        const SuperballShape shape(p);
        double largest = 0;
        for (const Vector3& u : sphere_points(20000)) largest = std::max(largest, norm((1 / shape.gauge(u)) * u));
        const double diagonal = norm((1 / shape.gauge(Vector3{1, 1, 1})) * Vector3{1, 1, 1});
        INFO("p = " << p);
        CHECK(largest <= shape.circumradius() * (1 + 1e-12));
        CHECK(std::max({largest, diagonal, 1.0}) == Approx(shape.circumradius()).epsilon(1e-12));
    }
}

TEST_CASE("the support point is on the boundary, attains the support value and is beaten by no sample") {
    Random random(11);
    const std::vector<Vector3> samples = sphere_points(4000);
    for (double p : shape_exponents) {
        const SuperballShape shape(p);
        std::vector<Vector3> directions{{1, 0, 0}, {0, -1, 0}, {1, 1, 1}, {1e-300, 0, -1e-300}, {1e300, 2e299, -1e300}, {1, 1e-12, 0}};
        for (int i = 0; i < 200; ++i) directions.push_back(random.uniform(0.1, 10) * random.unit_vector());
        for (const Vector3& n : directions) {
            const Vector3 x = shape.support_point(n);
            const double h = shape.support_value(n);
            INFO("p = " << p << ", n = (" << n[0] << ", " << n[1] << ", " << n[2] << ")");
            // A relative error e in x_i is 2p e in |x_i|^(2p): the tolerance grows with p.
            CHECK(std::fabs(shape.gauge_power(x) - 1) <= 1e-14 * std::max(1.0, 2 * p));
            CHECK(dot(n, x) == Approx(h).epsilon(1e-14));
            CHECK(shape.support_point(-1 * n) == -1 * x);  // odd, as K is symmetric
            double best_sample = -std::numeric_limits<double>::infinity();
            for (const Vector3& y : samples) best_sample = std::max(best_sample, dot(n, (1 / shape.gauge(y)) * y));
            CHECK(best_sample <= h * (1 + 1e-12));
            CHECK(best_sample >= h * 0.9);  // the samples come close (less so at vertices): h is not too large either
        }
        CHECK(shape.support_point({0, 0, 0}) == Vector3{0, 0, 0});
        CHECK(shape.support_value({0, 0, 0}) == 0);
    }
    // The octahedron's support point is a vertex; its support value the largest |n_i|.
    const SuperballShape octahedron(0.5);
    CHECK(octahedron.support_point({0.3, -0.9, 0.2}) == Vector3{0, -1, 0});
    CHECK(octahedron.support_value({0.3, -0.9, 0.2}) == 0.9);
}

TEST_CASE("axis-aligned superballs touch at center distance 2") {
    for (double p : {0.5, 1.0, 3.0, 1e3, 1e6}) {
        const SuperballShape shape(p);
        INFO("p = " << p);
        const Placement a = at({0.25, -3, 7});
        const Placement apart = at(a.center + Vector3{2 * (1 + 1e-9), 0, 0});
        const Placement into = at(a.center + Vector3{2 * (1 - 1e-9), 0, 0});
        CHECK_FALSE(overlapping(shape, a, apart));
        CHECK(overlapping(shape, a, into));
        const Separation gap = separation(shape, a, apart);
        REQUIRE_FALSE(gap.overlapping);
        CHECK(gap.distance == Approx(2e-9).epsilon(1e-5));
        CHECK(norm(gap.normal - Vector3{1, 0, 0}) < 1e-6);
        CHECK(separation(shape, a, into).overlapping);
        // The other way round: the same distance, the normal reversed.
        const Separation back = separation(shape, apart, a);
        CHECK(back.distance == Approx(gap.distance).epsilon(1e-5));
        CHECK(norm(back.normal + gap.normal) < 1e-6);
    }
}

TEST_CASE("a superball turned by 45 degrees about z touches at 1 + h_K(R^T e_x)") {
    const SuperballShape shape(3);
    const Matrix3 turn = rotation_matrix(axis_angle({0, 0, 1}, M_PI / 4));
    const double contact = 1 + shape.support_value(apply_transpose(turn, {1, 0, 0}));
    CHECK(contact > 2);  // the turned body reaches further along x than the unturned one
    const Placement a = at({0, 0, 0});
    for (double side : {1e-9, -1e-9, 1e-11, -1e-11}) {
        const Placement b = at({contact * (1 + side), 0, 0}, turn);
        INFO("relative offset " << side);
        CHECK(overlapping(shape, a, b) == (side < 0));
        const Separation result = separation(shape, a, b);
        CHECK(result.overlapping == (side < 0));
        if (side > 0) CHECK(result.distance == Approx(contact * side).epsilon(1e-3));
    }
}

// Tangent bodies at random orientations: a at the origin, b moved so that its support point in
// -n meets a's support point in n. Moved a further s along n, the bodies are exactly s apart;
// moved s < 0 back, they overlap whenever the midpoint of the contact is in both interiors
// (which the test checks: a polytope's vertex may graze past).
TEST_CASE("tangent placements at random orientations are told apart at 1e-9") {
    Random random(5);
    for (double p : shape_exponents) {
        const SuperballShape shape(p);
        int witnessed = 0, cases = 60;
        int most_iterations = 0;
        for (int i = 0; i < cases; ++i) {
            const Placement a = at({0, 0, 0}, random.rotation());
            const Matrix3 turn = random.rotation();
            const Vector3 n = random.unit_vector();
            const Vector3 contact = support_point(shape, a, n);
            const Vector3 tangent_center = contact - apply(turn, shape.support_point(apply_transpose(turn, -1 * n)));
            for (double s : {1e-9, -1e-9}) {
                const Placement b = at(tangent_center + s * n, turn);
                INFO("p = " << p << ", case " << i << ", s = " << s);
                const detail::GjkTrace trace = trace_of(shape, a, b);
                INFO("GJK: " << trace.iterations << " iterations, converged " << trace.converged << ", stalled " << trace.stalled);
                most_iterations = std::max(most_iterations, trace.iterations);
                CHECK_FALSE(trace.capped);
                const Separation result = separation(shape, a, b);
                if (s > 0) {
                    CHECK_FALSE(overlapping(shape, a, b));
                    REQUIRE_FALSE(result.overlapping);
                    CHECK(std::fabs(result.distance - s) <= 1e-12);
                    continue;
                }
                const Vector3 middle = contact + (s / 2) * n;
                const bool in_a = shape.gauge_power(apply_transpose(a.rotation, middle - a.center)) < 1;
                const bool in_b = shape.gauge_power(apply_transpose(b.rotation, middle - b.center)) < 1;
                if (!(in_a && in_b)) continue;
                ++witnessed;
                CHECK(overlapping(shape, a, b));
                CHECK(result.overlapping);
            }
        }
        INFO("p = " << p << ": " << witnessed << " overlaps witnessed, at most " << most_iterations << " iterations");
        CHECK(witnessed >= cases / 4);  // about 1/3 at p = 1/2, all of them above
        CHECK(most_iterations <= 100);  // the cap is 128: convergence, not the cap, ends a run
    }
}

// Random placements against brute force: center distances across [0, 2.1 circumradii], the
// verdicts checked with dense boundary samples and dense directions, not with GJK's own terms.
TEST_CASE("separation agrees with brute force over dense samples") {
    Random random(23);
    for (double p : shape_exponents) {
        const SuperballShape shape(p);
        const double radius = shape.circumradius();
        int apart = 0, meeting = 0, witnessed = 0;
        for (int i = 0; i < 30; ++i) {
            const Placement a = at(Vector3{random.uniform(-5, 5), random.uniform(-5, 5), random.uniform(-5, 5)}, random.rotation());
            // Every other case past the inscribed balls, where the verdicts are less obvious.
            const double center_distance = random.uniform(i % 2 ? 2 * shape.inradius() : 0, 2.1 * radius);
            const Placement b = at(a.center + center_distance * random.unit_vector(), random.rotation());
            INFO("p = " << p << ", case " << i << ", center distance " << center_distance);
            const Separation result = separation(shape, a, b);
            const double largest_gap = brute_force_largest_gap(shape, a, b, random);
            INFO("brute-force largest gap " << largest_gap);
            if (std::fabs(largest_gap) > 1e-9) {
                CHECK(overlapping(shape, a, b) == result.overlapping);
                CHECK(separation(shape, b, a).overlapping == result.overlapping);
            }
            if (result.overlapping) {
                ++meeting;
                // Every plane leaves a gap <= 0: no plane separates the bodies.
                CHECK(largest_gap <= 1e-9);
                if (largest_gap < -0.15) {
                    // Well into each other: a grid point of a lies in b as well.
                    bool found = false;
                    const int steps = 40;
                    for (int x = 0; x < steps && !found; ++x)
                        for (int y = 0; y < steps && !found; ++y)
                            for (int z = 0; z < steps && !found; ++z) {
                                const Vector3 body_point{-1 + (x + 0.5) * 2 / steps, -1 + (y + 0.5) * 2 / steps, -1 + (z + 0.5) * 2 / steps};
                                if (shape.gauge_power(body_point) >= 1) continue;
                                const Vector3 point = a.center + apply(a.rotation, body_point);
                                found = shape.gauge_power(apply_transpose(b.rotation, point - b.center)) < 1;
                            }
                    CHECK(found);
                    ++witnessed;
                }
                continue;
            }
            ++apart;
            CHECK(norm(result.normal) == Approx(1).epsilon(1e-12));
            CHECK(result.distance > 0);
            // The plane with the normal separates the samples of both boundaries.
            const std::vector<Vector3> samples_a = boundary_samples(shape, a, 1200), samples_b = boundary_samples(shape, b, 1200);
            double highest_a = -std::numeric_limits<double>::infinity(), lowest_b = std::numeric_limits<double>::infinity();
            for (const Vector3& x : samples_a) highest_a = std::max(highest_a, dot(result.normal, x));
            for (const Vector3& y : samples_b) lowest_b = std::min(lowest_b, dot(result.normal, y));
            CHECK(highest_a <= lowest_b + 1e-9);
            // The distance is at most that of the nearest sample pair (points of the bodies)...
            double nearest_pair = std::numeric_limits<double>::infinity();
            for (const Vector3& x : samples_a)
                for (const Vector3& y : samples_b) nearest_pair = std::min(nearest_pair, norm(x - y));
            CHECK(result.distance <= nearest_pair + 1e-9);
            if (center_distance > 2 * radius) {
                // ...and beyond the bounding spheres it is their gap, a lower bound.
                CHECK(result.distance == Approx(center_distance - 2 * radius).epsilon(1e-12));
                CHECK(result.distance <= largest_gap + 1e-12);
            } else {
                // ...and GJK's is the gap of its plane, which is at least the largest gap the
                // direction search finds (both are lower bounds on the distance)...
                CHECK(result.distance == Approx(plane_gap(shape, a, b, result.normal)).margin(1e-12));
                CHECK(result.distance >= largest_gap - 1e-9);
                // ...and at most the distance of the support points in +-normal, two points of
                // the bodies. They are the nearest pair for the exact normal; for a normal off by
                // an angle e, their distance is off by e over the curvature, and e after
                // convergence is about the square root of the gap's 1e-10: a close pair only
                // where the curvature is moderate (near 1/2 and for p >= 50 the support point
                // turns fast near edges and vertices).
                const double pair = norm(support_point(shape, b, -1 * result.normal) - support_point(shape, a, result.normal));
                CHECK(result.distance <= pair + 1e-9);
                if (p >= 1 && p <= 3) CHECK(pair - result.distance <= 1e-4 * result.distance + 1e-9);
            }
        }
        INFO("p = " << p << ": " << apart << " apart, " << meeting << " overlapping, " << witnessed << " by a grid point");
        CHECK(apart >= 4);
        CHECK(meeting >= 4);
    }
}

// Where GJK's simplices degenerate: flat faces of near-cubes against each other (exactly
// parallel, or turned by tiny angles), and tips of octahedra against each other.
TEST_CASE("degenerate contacts end with the right verdict") {
    for (double p : {1e3, 1e6}) {
        const SuperballShape shape(p);
        for (double angle : {0.0, 1e-12, 1e-7, 1e-3}) {
            // b rests on the face x = 1 of a, touching it at `contact`, which lies inside the flat
            // part of that face (where a's outer normal is e_1), then moves s along e_1.
            const Matrix3 turn = rotation_matrix(axis_angle(Vector3{0.6, 0, 0.8}, angle));
            const Vector3 contact{1, 0.2, -0.3};
            const Vector3 tangent_center = contact - apply(turn, shape.support_point(apply_transpose(turn, {-1, 0, 0})));
            for (double s : {1e-9, -1e-9}) {
                const Placement a = at({0, 0, 0}), b = at(tangent_center + Vector3{s, 0, 0}, turn);
                INFO("p = " << p << ", angle " << angle << ", s = " << s);
                const detail::GjkTrace trace = trace_of(shape, a, b);
                INFO("GJK: " << trace.iterations << " iterations, converged " << trace.converged << ", stalled " << trace.stalled);
                CHECK_FALSE(trace.capped);
                CHECK(overlapping(shape, a, b) == (s < 0));
                const Separation result = separation(shape, a, b);
                REQUIRE(result.overlapping == (s < 0));
                if (s > 0) CHECK(std::fabs(result.distance - s) <= 1e-12);
            }
        }
    }
    // Octahedra tip to tip along x, the tip of b offset sideways by a multiple of |s|: the
    // tips' cones meet iff the offset's l1 norm is below the overlap |s| along x.
    const SuperballShape octahedron(0.5);
    for (double s : {1e-9, -1e-9})
        for (double offset : {0.0, 0.5, 2.0})
            for (double angle : {0.0, 0.3}) {
                if (angle != 0 && offset != 0) continue;  // a turn about x changes b's cone
                const Placement a = at({0, 0, 0});
                const Placement b = at({2 + s, 0.6 * offset * std::fabs(s), -0.4 * offset * std::fabs(s)},
                                       rotation_matrix(axis_angle({1, 0, 0}, angle)));
                const bool meet = s < 0 && offset < 1;
                INFO("s = " << s << ", offset " << offset << ", angle " << angle);
                CHECK_FALSE(trace_of(octahedron, a, b).capped);
                CHECK(overlapping(octahedron, a, b) == meet);
                CHECK(separation(octahedron, a, b).overlapping == meet);
            }
    // Coincident bodies overlap; so do bodies whose inscribed balls meet.
    const SuperballShape cube_like(1e6);
    CHECK(overlapping(cube_like, at({1, 2, 3}), at({1, 2, 3})));
    CHECK(separation(cube_like, at({1, 2, 3}), at({1, 2, 3})).overlapping);
    CHECK(overlapping(octahedron, at({0, 0, 0}), at({2 / std::sqrt(3.0) - 1e-9, 0, 0}, rotation_matrix(axis_angle({0, 1, 0}, 1)))));
}
