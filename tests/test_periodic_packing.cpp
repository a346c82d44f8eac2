// The proof of a periodic packing of rotated superballs (problems/periodic/periodic_packing.hpp): exact
// rotations, the close-pair enumeration, planes that prove touching pairs, the scale that
// separates overlapping ones, densities against mpmath (tests/data/golden.json), two backends
// that agree, and random configurations whose proved packings sampled points never refute.
#include <cmath>
#include <random>

#include "superpack/problems/periodic/periodic_packing.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

PeriodicPacking cubic(const Rational& p, const Rational& side, std::vector<RationalVector3> centers,
                      std::vector<std::array<Rational, 4>> quaternions) {
    PeriodicPacking packing;
    packing.p = p;
    packing.cell = {{{side, 0, 0}, {0, side, 0}, {0, 0, side}}};
    packing.centers = std::move(centers);
    packing.quaternions = std::move(quaternions);
    return packing;
}

const std::array<Rational, 4> unrotated{1, 0, 0, 0};

double gauge_power(const std::array<double, 3>& x, double p) {
    return std::pow(std::fabs(x[0]), 2 * p) + std::pow(std::fabs(x[1]), 2 * p) + std::pow(std::fabs(x[2]), 2 * p);
}

std::array<double, 3> rotate(const Basis<Rational>& r, const std::array<double, 3>& x, bool transposed) {
    std::array<double, 3> y{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) y[i] += (transposed ? r[j][i] : r[i][j]).get_d() * x[j];
    return y;
}

// The least gauge power, in the body frame of `second`, of points sampled inside `first` for
// the pair's image: >= 1 for disjoint interiors (up to rounding), < 1 would be an overlap.
double least_sampled(const PeriodicPacking& packing, const PairSeparation& pair, std::mt19937_64& random) {
    const double p = packing.p.get_d();
    const Basis<Rational> first = rotation_of(packing.quaternions[pair.first]), second = rotation_of(packing.quaternions[pair.second]);
    std::array<double, 3> d{};
    for (int c = 0; c < 3; ++c)
        d[c] = Rational(packing.centers[pair.second][c] - packing.centers[pair.first][c] + pair.shift[0] * packing.cell[0][c] +
                        pair.shift[1] * packing.cell[1][c] + pair.shift[2] * packing.cell[2][c])
                   .get_d();
    std::uniform_real_distribution<double> coordinate(-1, 1);
    double least = HUGE_VAL;
    for (int n = 0; n < 20000; ++n) {
        std::array<double, 3> y{coordinate(random), coordinate(random), coordinate(random)};
        const double g = gauge_power(y, p);
        // Points pushed towards the boundary of K, where contacts are.
        const double toward = std::pow(g, -1 / (2 * p)) * (n % 2 ? 1 : std::pow(coordinate(random) * 0.5 + 0.5, 0.01));
        for (double& x : y) x *= toward;
        const std::array<double, 3> x = rotate(first, y, false);
        const std::array<double, 3> local = rotate(second, {x[0] - d[0], x[1] - d[1], x[2] - d[2]}, true);
        least = std::min(least, gauge_power(local, p));
    }
    return least;
}

}  // namespace

TEST_CASE("rational quaternions give exact rotations", "") {
    const Basis<Rational> r = rotation_of({Rational(3, 7), Rational(-2, 5), Rational(1, 3), Rational(5, 11)});
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const Rational product = r[i][0] * r[j][0] + r[i][1] * r[j][1] + r[i][2] * r[j][2];
            CHECK(product == (i == j ? 1 : 0));
        }
    CHECK(determinant(r) == 1);
    // 90 degrees about z, unnormalised: e_x -> e_y.
    const Basis<Rational> quarter = rotation_of({1, 0, 0, 1});
    CHECK(quarter[1][0] == 1);
    CHECK(quarter[0][0] == 0);
    CHECK_THROWS_AS(rotation_of({0, 0, 0, 0}), InputError);
    CHECK(dyadic_near(0.1, 40) * mpz_class(1099511627776L) == mpz_class(static_cast<long>(std::llround(0.1 * 1099511627776.0))));
    // In lowest terms, as GMP's comparisons need: 109951162778 / 2^40 is even over even.
    CHECK(dyadic_near(0.1, 40).get_den() == mpz_class(549755813888L));
    CHECK(dyadic_near(-3.5, 2) == Rational(-7, 2));
}

TEMPLATE_TEST_CASE("touching balls are proved at scale 1, with density pi/6", "", Binary64, Arb128) {
    const TestType field;
    const auto proof = certify_periodic_packing(cubic(1, 2, {{0, 0, 0}}, {unrotated}), {}, field);
    REQUIRE(proof.status == Outcome::proved);
    CHECK(proof.scale == 1);
    CHECK(proof.radius == 1);
    CHECK(proof.determinant == 8);
    CHECK(meets((*proof.phi), golden()["constants"]["pi_over_6"].get<std::string>()));
    CHECK(width_upper((*proof.phi)) < width_budget(field));
}

TEMPLATE_TEST_CASE("overlapping balls are scaled apart by the least factor", "", Binary64, Arb128) {
    const TestType field;
    const auto proof = certify_periodic_packing(cubic(1, Rational(19, 10), {{0, 0, 0}}, {unrotated}), {}, field);
    REQUIRE(proof.status == Outcome::proved);
    // Scaled, the three axis neighbours are more than 2 = 2r apart, beyond the cutoff, so no
    // pair is left to separate (unscaled, those three were the only ones within it).
    CHECK(proof.pairs.empty());
    CHECK(proof.scale >= Rational(20, 19));
    CHECK(proof.scale <= Rational(20, 19) * (1 + Rational(1, 100000000)));
    // phi = (pi/6) (2 / (1.9 s))^3 <= pi/6, within 1e-7 of it.
    const Ball pi_over_6 = reference(golden()["constants"]["pi_over_6"].get<std::string>());
    CHECK(certainly_less(as_ball((*proof.phi)), pi_over_6));
    CHECK(certainly_less(pi_over_6 * BallField{64}.rational(Rational(9999999, 10000000)), as_ball((*proof.phi))));
}

TEMPLATE_TEST_CASE("two touching superballs at p = 2, and a rotated neighbour", "", Binary64, Arb128) {
    const TestType field;
    const auto touching = certify_periodic_packing(cubic(2, 4, {{0, 0, 0}, {2, 0, 0}}, {unrotated, unrotated}), {}, field);
    REQUIRE(touching.status == Outcome::proved);
    CHECK(touching.pairs.size() == 2);  // (2, 0, 0) and its image (-2, 0, 0)
    CHECK(touching.scale <= 1 + Rational(1, 1000000000));
    // phi = 2 V(2) / 64.
    const auto volume = reference(golden()["constants"]["superball_volume_p2"].get<std::string>());
    Ball meet(256);
    const Ball expected = volume * BallField{256}.rational(Rational(2, 64));
    CHECK(intersect(meet, as_ball((*touching.phi) * field.rational(touching.scale * touching.scale * touching.scale)), expected));

    // 45 degrees about z (w = cos 22.5, z = sin 22.5, rounded: any rational quaternion is a
    // rotation): its extent along x is h_K(R^T e_x) = 2^(3/4) / sqrt 2 = 1.18920..., so the
    // pair touches at a centre distance 2.18920...; at 2.25 it is apart, at 2.1 it must be scaled.
    const std::array<Rational, 4> turned{dyadic_near(std::cos(M_PI / 8), 30), 0, 0, dyadic_near(std::sin(M_PI / 8), 30)};
    const auto guess = [](std::size_t, std::size_t, const std::array<double, 3>& d) {
        return std::array<double, 3>{d[0] > 0 ? 1.0 : -1.0, 0, 0};
    };
    const auto apart = certify_periodic_packing(cubic(2, Rational(9, 2), {{0, 0, 0}, {Rational(9, 4), 0, 0}}, {unrotated, turned}), guess, field);
    REQUIRE(apart.status == Outcome::proved);
    CHECK(apart.scale == 1);
    const auto close = certify_periodic_packing(cubic(2, Rational(42, 10), {{0, 0, 0}, {Rational(21, 10), 0, 0}}, {unrotated, turned}), guess, field);
    REQUIRE(close.status == Outcome::proved);
    const double contact = 1 + std::pow(2.0, 0.75) / std::sqrt(2.0);
    CHECK(close.scale.get_d() >= contact / 2.1 * (1 - 1e-6));
    CHECK(close.scale.get_d() <= contact / 2.1 * (1 + 1e-6));
}

TEST_CASE("the two backends agree on a proved density", "") {
    const auto packing = cubic(Rational(3, 2), Rational(21, 10), {{0, 0, 0}}, {std::array<Rational, 4>{2, 1, 0, 0}});
    const auto binary64 = certify_periodic_packing(packing, {}, DoubleField{});
    const auto arb = certify_periodic_packing(packing, {}, BallField{200});
    REQUIRE(binary64.status == Outcome::proved);
    REQUIRE(arb.status == Outcome::proved);
    CHECK(binary64.scale == arb.scale);
    CHECK(overlaps(as_ball((*binary64.phi)), (*arb.phi)));
}

TEST_CASE("proved random packings are never refuted by sampled points", "") {
    std::mt19937_64 random(2026);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (const Rational& p : {Rational(1, 2), Rational(3, 5), Rational(3, 2), Rational(3)}) {
        for (int trial = 0; trial < 3; ++trial) {
            PeriodicPacking packing;
            packing.p = p;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) packing.cell[i][j] = dyadic_near((i == j ? 2.6 : 0) + 0.6 * unit(random), 20);
            for (int n = 0; n < 2; ++n) {
                packing.centers.push_back({dyadic_near(unit(random), 20), dyadic_near(unit(random), 20), dyadic_near(unit(random), 20)});
                packing.quaternions.push_back({dyadic_near(unit(random), 20), dyadic_near(unit(random), 20),
                                               dyadic_near(unit(random), 20), dyadic_near(unit(random), 20)});
            }
            const auto proof = certify_periodic_packing(packing, {}, DoubleField{});
            REQUIRE(proof.status == Outcome::proved);
            CHECK(proof.scale >= 1);
            for (const PairSeparation& pair : proof.pairs) CHECK(least_sampled(proof.packing, pair, random) >= 1 - 1e-9);
        }
    }
}

TEST_CASE("the certification refuses what it is not for", "") {
    CHECK_THROWS_AS(certify_periodic_packing(cubic(Rational(2, 5), 2, {{0, 0, 0}}, {unrotated}), {}, DoubleField{}), InputError);
    CHECK_THROWS_AS(certify_periodic_packing(cubic(1, 0, {{0, 0, 0}}, {unrotated}), {}, DoubleField{}), InputError);
    CHECK_THROWS_AS(certify_periodic_packing(cubic(1, 2, {{0, 0, 0}}, {{0, 0, 0, 0}}), {}, DoubleField{}), InputError);
    CHECK_THROWS_AS(certify_periodic_packing(cubic(1, 2, {}, {}), {}, DoubleField{}), InputError);
    // A needle-thin cell would need too many shifts per pair: refused, never a long loop.
    PeriodicPacking thin = cubic(1, 2, {{0, 0, 0}}, {unrotated});
    thin.cell[2][2] = Rational(1, 1000000);
    CHECK_THROWS_AS(certify_periodic_packing(thin, {}, DoubleField{}), InputError);
}
