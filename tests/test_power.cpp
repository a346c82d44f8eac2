// Powers of intervals whose base reaches 0: x^y, |x|^y and sign(x)|x|^y must enclose
// the true range, which is unbounded when the exponent may be negative, and the derivative of
// |x|^y across 0 must be unbounded for y < 1. Each enclosure is checked against MPFR at 256
// bits, directed, at points of the argument box (x near 0 included), in both backends.
#include <mpfr.h>

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "superpack/arith/mpfr_bounds.hpp"
#include "superpack/solve/krawczyk.hpp"
#include "superpack/solve/newton.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

// Does the enclosure e hold x^y (MPFR at 256 bits, rounded down and up)? x >= 0 and y are
// doubles, so exact; x = 0 needs y >= 0.
template <class I>
bool holds_power(const I& e, double x, double y) {
    mpfr_t base, exponent, down, up, lo, hi;
    mpfr_inits2(256, base, exponent, down, up, static_cast<mpfr_ptr>(nullptr));
    mpfr_inits2(1024, lo, hi, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_d(base, x, MPFR_RNDN);
    mpfr_set_d(exponent, y, MPFR_RNDN);
    mpfr_pow(down, base, exponent, MPFR_RNDD);
    mpfr_pow(up, base, exponent, MPFR_RNDU);
    get_bounds(lo, hi, e);
    const bool ok = mpfr_cmp(lo, down) <= 0 && mpfr_cmp(up, hi) <= 0;
    mpfr_clears(base, exponent, down, up, lo, hi, static_cast<mpfr_ptr>(nullptr));
    return ok;
}

// The same for a signed value v = sign * x^y.
template <class I>
bool holds_signed_power(const I& e, double sign, double x, double y) {
    return holds_power(sign < 0 ? -e : e, x, y);
}

// Points of [lo, hi]: the ends, the middle and, where the box reaches 0, points approaching 0.
std::vector<double> points_of(double lo, double hi) {
    std::vector<double> points{lo, hi, lo / 2 + hi / 2};
    if (lo <= 0 && 0 <= hi)
        for (double tiny : {0x1p-10, 0x1p-40, 0x1p-200, 0x1p-1000}) {
            if (tiny <= hi) points.push_back(tiny);
            if (-tiny >= lo) points.push_back(-tiny);
        }
    return points;
}

// [lo, hi] as the hull of two exact points (a ball made by from_doubles(0, b) would reach a
// rounding error below 0; a ball hull of nonnegative points keeps its lower end at 0).
template <class Field>
typename Field::Interval box(const Field& field, double lo, double hi) {
    const auto zero = field.integer(0);
    return hull(from_doubles(zero, lo, lo), from_doubles(zero, hi, hi));
}

struct PowerCase {
    double x_lo, x_hi, y_lo, y_hi;
};

// Bases reaching 0 and away from it, exponents negative, zero, positive and straddling 0.
const std::vector<PowerCase>& power_cases() {
    static const std::vector<PowerCase> cases{
        {0, 1, -1, -1},        {0, 4, 1.5, 1.5},       {0, 4, 0, 0},         {0, 4, -0.5, 0.5},
        {0, 4, 0, 0.5},        {0, 4, -0.5, 0},        {0, 0.25, -2, -1},    {0, 0.25, -0.5, 2},
        {0.25, 4, -1, 2},      {0.5, 0.5, -3, -3},     {0, 2, 0.25, 3},      {0, 0x1p-30, -0.75, -0.25},
        {3, 3, -0.5, 0.5},     {0x1p-20, 1, -1, -1},   {0, 0, 2, 2},         {0, 0, 0, 0},
        {0, 0, 0, 1}};
    return cases;
}

}  // namespace

TEMPLATE_TEST_CASE("x^y encloses the true range when the base reaches 0, unbounded for exponents below 0", "",
                   Binary64, Arb128, Arb400) {
    const TestType field;
    for (const PowerCase& c : power_cases()) {
        const auto x = box(field, c.x_lo, c.x_hi), y = box(field, c.y_lo, c.y_hi);
        INFO("[" << c.x_lo << ", " << c.x_hi << "]^[" << c.y_lo << ", " << c.y_hi << "]");
        const auto power = pow_nonneg(x, y);
        for (double a : points_of(c.x_lo, c.x_hi))
            for (double b : points_of(c.y_lo, c.y_hi)) {
                if (a < 0 || (a == 0 && b < 0)) continue;  // outside the domain
                INFO("at x = " << a << ", y = " << b);
                CHECK(holds_power(power, a, b));
                // |x|^y on the symmetric box [-hi, hi] holds the same values.
                CHECK(holds_power(pow_abs(box(field, -c.x_hi, c.x_hi), y), a, b));
            }
        // Unbounded exactly when the base reaches 0 and the exponent can be negative.
        const bool unbounded = c.x_lo == 0 && c.y_lo < 0;
        CHECK(bounded(power) == !unbounded);
    }
    // The tightness of the binary64 ends: [0, 1]^-1 = [1, +inf], [0, 4]^[-1/2, 0] = [1/2, +inf].
    if constexpr (std::is_same_v<TestType, Binary64>) {
        const DInterval inverse = pow_nonneg(box(field, 0, 1), box(field, -1, -1));
        CHECK(inverse.lower() >= 1 - 0x1p-40);
        CHECK(inverse.upper() == std::numeric_limits<double>::infinity());
        CHECK(pow_nonneg(box(field, 0, 4), box(field, -0.5, 0)).lower() >= 0.5 - 0x1p-40);
        CHECK(pow_nonneg(box(field, 0, 4), box(field, 0, 0)).lower() == 1);
    }
    // The point 0 with an exponent that may be negative has no real power: refused.
    CHECK_THROWS_AS(pow_nonneg(field.integer(0), box(field, -1, -1)), std::domain_error);
    CHECK_THROWS_AS(pow_nonneg(field.integer(0), box(field, -1, 1)), std::domain_error);
    CHECK_THROWS_AS(pow_nonneg(box(field, -1, 1), box(field, 2, 2)), std::domain_error);
}

TEMPLATE_TEST_CASE("x^n and x^(1/2), x^(1/4) by products and sqrt: enclosures, exact at dyadic points, the general path elsewhere",
                   "", Binary64, Arb128) {
    const TestType field;
    // Bases from subnormal to huge, reaching 0 and not; every exponent of the fast path.
    const std::vector<std::pair<double, double>> bases{{0, 1},       {0x1p-1060, 0x1p-1050}, {0.3, 0.7},
                                                       {1.5, 1.5},   {0.1, 0.1},             {3, 1e30},
                                                       {0x1p-20, 2}, {16, 16}};
    for (const double n : {1.0, 2.0, 3.0, 4.0, 5.0, 7.0, 8.0, 0.5, 0.25})
        for (const auto& [lo, hi] : bases) {
            const auto x = box(field, lo, hi), y = box(field, n, n);
            INFO("[" << lo << ", " << hi << "]^" << n);
            const auto power = pow_nonneg(x, y);
            for (double a : points_of(lo, hi)) CHECK(holds_power(power, a, n));
            CHECK(certainly_nonnegative(power));
        }
    // Exact where the true power is a double: 1.5^4 = 5.0625, 16^(1/4) = 2, 16^(1/2) = 4.
    CHECK(width_upper(pow_nonneg(box(field, 1.5, 1.5), box(field, 4, 4))) == 0);
    CHECK(contains(pow_nonneg(box(field, 1.5, 1.5), box(field, 4, 4)), from_doubles(field.integer(0), 5.0625, 5.0625)));
    CHECK(width_upper(pow_nonneg(box(field, 16, 16), box(field, 0.25, 0.25))) == 0);
    CHECK(contains(pow_nonneg(box(field, 16, 16), box(field, 0.5, 0.5)), field.integer(4)));
    // Not a point, or another point: the general path, still an enclosure (9 is past the table).
    for (const auto& [y_lo, y_hi] : std::vector<std::pair<double, double>>{{4, 4.5}, {9, 9}, {0.75, 0.75}, {3.5, 3.5}}) {
        const auto power = pow_nonneg(box(field, 0.3, 1.7), box(field, y_lo, y_hi));
        for (double a : points_of(0.3, 1.7))
            for (double b : points_of(y_lo, y_hi)) CHECK(holds_power(power, a, b));
    }
}

TEMPLATE_TEST_CASE("sign(x)|x|^y across 0 is bounded for y >= 0 and the whole line for y < 0", "", Binary64, Arb128) {
    const TestType field;
    for (const auto& [y_lo, y_hi] : std::vector<std::pair<double, double>>{{-0.5, -0.5}, {-0.5, 0.5}, {0, 0}, {0.5, 0.5}, {0, 2}}) {
        const auto y = box(field, y_lo, y_hi);
        const auto kernel = pow_signed(box(field, -1, 0.5), y);
        INFO("y = [" << y_lo << ", " << y_hi << "]");
        for (double a : points_of(-1, 0.5))
            for (double b : points_of(y_lo, y_hi))
                if (a != 0) CHECK(holds_signed_power(kernel, a, std::fabs(a), b));
        CHECK(bounded(kernel) == (y_lo >= 0));
    }
    // y = 0 exactly: sign(x) over a box across 0 is [-1, 1], also at the point 0.
    CHECK(contains(pow_signed(field.integer(0), field.integer(0)), box(field, -1, 1)));
    CHECK(contains(box(field, -1, 1), pow_signed(box(field, -1, 0.5), field.integer(0))));
}

TEMPLATE_TEST_CASE("the derivative of |x|^y across 0: unbounded for y < 1, [-1, 1] for y = 1, bounded above", "",
                   Binary64, Arb128) {
    const TestType field;
    const auto x = box(field, -0.125, 0.5);
    for (double y : {0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0}) {
        INFO("y = " << y);
        const auto exponent = box(field, y, y);
        const Jet<typename TestType::Interval> jet = pow_abs(variable(x), exponent);
        const Jet<typename TestType::Interval> both = pow_abs(variable(x), constant(exponent));
        // d/dx |x|^y = y sign(x) |x|^(y-1) at points of the box, 0 excluded.
        for (double a : points_of(-0.125, 0.5)) {
            if (a == 0) continue;
            INFO("at x = " << a);
            const auto slope = jet.derivative / exponent;  // sign(a) |a|^(y-1)
            CHECK(holds_signed_power(slope, a, std::fabs(a), y - 1));
            CHECK(holds_signed_power(both.derivative / exponent, a, std::fabs(a), y - 1));
        }
        CHECK(bounded(jet.derivative) == (y >= 1));
        CHECK(bounded(both.derivative) == (y >= 1));
        // p = 1/2: |x| is 1-Lipschitz, so [-1, 1] bounds every slope across the kink (a ball
        // product rounds its radius up a little).
        const double slack = std::is_same_v<TestType, Binary64> ? 0 : 0x1p-20;
        if (y == 1.0) CHECK(contains(box(field, -1 - slack, 1 + slack), jet.derivative));
    }
    // x^y for x >= 0 near 0: y x^(y-1) is unbounded for y < 1, also at the point 0.
    const auto half = box(field, 0.5, 0.5);
    const auto root = pow_nonneg(variable(box(field, 0, 0.5)), half);
    CHECK(!bounded(root.derivative));
    CHECK(holds_power(root.derivative / half, 0x1p-100, -0.5));
    CHECK(!bounded(pow_nonneg(variable(field.integer(0)), half).derivative));
    CHECK(bounded(pow_nonneg(variable(box(field, 0, 0.5)), box(field, 1.5, 1.5)).derivative));
}

namespace {

// f(x) = sqrt(x) - 1/2 as x^(1/2) on [0, 1]: one root, at 1/4, and f' = x^(-1/2) / 2 is
// unbounded at 0.
struct RootOfSquareRoot {
    template <class S>
    S operator()(const S& x) const {
        const auto field = scalar_field(x);
        return pow_nonneg(x, field.rational(Rational(1, 2))) - field.rational(Rational(1, 2));
    }
    template <class S>
    std::vector<S> operator()(const std::vector<S>& x) const {
        return {(*this)(x[0])};
    }
};

}  // namespace

TEMPLATE_TEST_CASE("Newton and Krawczyk on an unbounded derivative are undecided, never wrong", "", Binary64, Arb128) {
    const TestType field;
    const auto x = box(field, 0, 1);
    // A bounded (wrong) derivative once made Krawczyk cut the root 1/4 out of the box and
    // then report "no root".
    const auto krawczyk = krawczyk_isolate(RootOfSquareRoot{}, std::vector<typename TestType::Interval>{x}, 0.0, 20);
    CHECK(krawczyk.status == RootStatus::undecided);
    const auto newton = newton_isolate(RootOfSquareRoot{}, x, 0.0, 20);
    CHECK(newton.status != RootStatus::none);
    if (newton.status == RootStatus::unique) CHECK(contains(newton.box, field.rational(Rational(1, 4))));
    // On a box away from 0 the derivative is bounded and both prove the root.
    const auto away = box(field, 0.125, 0.5);
    const auto proved = krawczyk_isolate(RootOfSquareRoot{}, std::vector<typename TestType::Interval>{away}, 0.0, 40);
    REQUIRE(proved.status == RootStatus::unique);
    CHECK(contains(proved.box[0], field.rational(Rational(1, 4))));
}
