// The binary64 backend's own arithmetic: directed + - * / sqrt made from round-to-nearest
// results (interval_double.hpp) and exp, log, Gamma from series with proved error bounds
// (src/elementary_double.cpp). Every enclosure is checked against MPFR at 256 bits with
// directed rounding, an independent and correctly rounded reference, on random and on
// hand-picked hard arguments; and the enclosures must stay tight, so a loose bound fails.
#include <gmpxx.h>
#include <mpfr.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "support.hpp"

using namespace superpack;

namespace {

using MpfrFunction = int (*)(mpfr_t, const mpfr_t, mpfr_rnd_t);

// Does [lo, hi] hold f(x) as MPFR encloses it at 256 bits?
bool encloses(const DInterval& y, MpfrFunction f, double x) {
    mpfr_t a, down, up;
    mpfr_inits2(256, a, down, up, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_d(a, x, MPFR_RNDN);
    f(down, a, MPFR_RNDD);
    f(up, a, MPFR_RNDU);
    const bool ok = mpfr_cmp_d(down, y.lower()) >= 0 && mpfr_cmp_d(up, y.upper()) <= 0;
    mpfr_clears(a, down, up, static_cast<mpfr_ptr>(nullptr));
    return ok;
}

// Width in units of the last place of the upper end.
double ulps(const DInterval& y) {
    const double scale = std::max(std::fabs(y.lower()), std::fabs(y.upper()));
    return scale == 0 ? 0 : (y.upper() - y.lower()) / (scale * std::numeric_limits<double>::epsilon());
}

// Exponents spread over the whole binary64 range, with a random 53-bit mantissa.
double random_positive(std::mt19937_64& random, int min_exponent, int max_exponent) {
    std::uniform_int_distribution<int> exponent(min_exponent, max_exponent);
    std::uniform_real_distribution<double> mantissa(1, 2);
    return std::ldexp(mantissa(random), exponent(random));
}

}  // namespace

TEST_CASE("exp of binary64 intervals encloses MPFR's value and stays within a few ulps") {
    std::mt19937_64 random(20261125);
    std::uniform_real_distribution<double> argument(-700, 700);
    std::vector<double> points{0.0, 1.0, -1.0, 0x1p-1074, -0x1p-1074, 1e-300, 0.6931471805599453, 700, -700,
                               0.6931471805599453 / 512, -0.6931471805599453 / 512, 709.7, -744, 1e3, -1e3};
    for (int k = 0; k < 20000; ++k) points.push_back(argument(random));
    for (int k = 0; k < 2000; ++k) points.push_back((k % 2 ? -1 : 1) * random_positive(random, -60, 0));
    double worst = 0;
    for (double x : points) {
        const DInterval y = exp(DInterval(x));
        INFO("x = " << x);
        REQUIRE(encloses(y, mpfr_exp, x));
        if (std::fabs(x) <= 700) worst = std::max(worst, ulps(y));
    }
    CHECK(worst <= 12);
}

TEST_CASE("log of binary64 intervals encloses MPFR's value, subnormals and powers of two included") {
    std::mt19937_64 random(7);
    std::vector<double> points{1.0, 2.0, 0.5, 3.0, 10.0, 0x1p-1074, 0x1p-1022, std::numeric_limits<double>::max(),
                               1 + 0x1p-52, 1 - 0x1p-53, 1 + 1.0 / 256, 1 + 1.0 / 128, 1.99999999999999978};
    for (int k = 0; k < 20000; ++k) points.push_back(random_positive(random, -1074, 1023));
    for (int k = 0; k < 4000; ++k) points.push_back(random_positive(random, -2, 1));
    double worst = 0;
    for (double x : points) {
        const DInterval y = log(DInterval(x));
        INFO("x = " << x);
        REQUIRE(encloses(y, mpfr_log, x));
        // Near 1 the value is tiny and only an absolute bound is meaningful.
        if (std::fabs(x - 1) > 0.01 && x > 0x1p-1000 && x < 0x1p1000) worst = std::max(worst, ulps(y));
    }
    CHECK(worst <= 12);
    CHECK_THROWS(log(DInterval(0.0)));
    CHECK_THROWS(log(DInterval(-1.0, 2.0)));
}

TEST_CASE("log1p of binary64 intervals encloses MPFR's value with a relative error of a few ulps, tiny x included") {
    std::mt19937_64 random(1951);
    std::vector<double> points{0.0, 0x1p-1074, -0x1p-1074, 1e-300, -1e-300, 0.0625, -0.0625, 0.0625000000000001,
                               -0.0624999999999999, 1.0, -0.5, -0.9999999999999999, 1e300, 3.4657359027997265e-7};
    for (int k = 0; k < 20000; ++k) points.push_back((k % 2 ? -1 : 1) * random_positive(random, -1074, -1));
    for (int k = 0; k < 4000; ++k) points.push_back(random_positive(random, -8, 1000));
    for (int k = 0; k < 4000; ++k) points.push_back((k % 2 ? -1 : 1) * random_positive(random, -10, -4));
    double worst = 0;
    for (double x : points) {
        if (!(x > -1)) continue;
        const DInterval y = log1p(DInterval(x));
        INFO("x = " << x);
        REQUIRE(encloses(y, mpfr_log1p, x));
        if (std::fabs(x) > 0x1p-1000) worst = std::max(worst, ulps(y));
    }
    CHECK(worst <= 12);
    // A wide argument holds the values at both ends; x <= -1 is refused.
    const DInterval wide = log1p(DInterval(-0.01, 0.5));
    CHECK(encloses(wide, mpfr_log1p, -0.01));
    CHECK(encloses(wide, mpfr_log1p, 0.5));
    CHECK_THROWS(log1p(DInterval(-1.0, 0.0)));
}

TEST_CASE("expm1 of binary64 intervals encloses MPFR's value with a relative error of a few ulps, tiny x included") {
    std::mt19937_64 random(1950);
    std::vector<double> points{0.0, 0x1p-1074, -0x1p-1074, 1e-300, -1e-300, 0.5, -0.5, 0.5000000000000001,
                               -0.5000000000000001, 1.0, -40.0, 700, -3.4657359027997265e-7, -0.6931471805599453};
    for (int k = 0; k < 20000; ++k) points.push_back((k % 2 ? -1 : 1) * random_positive(random, -1074, -1));
    for (int k = 0; k < 4000; ++k) points.push_back((k % 2 ? -1 : 1) * random_positive(random, -3, 9));
    double worst = 0;
    for (double x : points) {
        if (x > 700) continue;
        const DInterval y = expm1(DInterval(x));
        INFO("x = " << x);
        REQUIRE(encloses(y, mpfr_expm1, x));
        if (std::fabs(x) > 0x1p-1000) worst = std::max(worst, ulps(y));
    }
    CHECK(worst <= 12);
    const DInterval wide = expm1(DInterval(-0.75, 0.25));
    CHECK(encloses(wide, mpfr_expm1, -0.75));
    CHECK(encloses(wide, mpfr_expm1, 0.25));
}

TEST_CASE("Gamma of binary64 intervals encloses MPFR's value on and off the series range") {
    std::mt19937_64 random(1125);
    std::uniform_real_distribution<double> argument(1.0 / 16, 8);
    std::vector<double> points{1.0, 2.0, 3.0, 0.5, 1.5, 1.4616321449683622, 1.0 / 16, 7.999999999999999, 8, 20, 0.01};
    for (int k = 0; k < 20000; ++k) points.push_back(argument(random));
    double worst = 0;
    for (double x : points) {
        const DInterval y = gamma(DInterval(x));
        INFO("x = " << x);
        REQUIRE(encloses(y, mpfr_gamma, x));
        if (x >= 1.0 / 16 && x < 8) worst = std::max(worst, ulps(y));
    }
    CHECK(worst <= 16);
}

TEST_CASE("narrow and wide interval arguments hold the values at both ends") {
    std::mt19937_64 random(99);
    std::uniform_real_distribution<double> argument(-50, 50), width_exponent(-52, 2);
    for (int k = 0; k < 5000; ++k) {
        const double lo = argument(random);
        const double hi = lo + std::ldexp(std::fabs(lo) + 1, static_cast<int>(width_exponent(random)));
        const DInterval x(lo, hi);
        const DInterval e = exp(x);
        REQUIRE(encloses(e, mpfr_exp, lo));
        REQUIRE(encloses(e, mpfr_exp, hi));
        const double a = std::exp(lo / 8), b = std::exp(hi / 8);  // positive ends for log and Gamma
        const DInterval l = log(DInterval(a, b));
        REQUIRE(encloses(l, mpfr_log, a));
        REQUIRE(encloses(l, mpfr_log, b));
        if (a > 1.0 / 16 && b < 8) {
            const DInterval g = gamma(DInterval(a, b));
            REQUIRE(encloses(g, mpfr_gamma, a));
            REQUIRE(encloses(g, mpfr_gamma, b));
        }
    }
}

TEST_CASE("Gamma at the edges of the series' range: widest narrow arguments and the ends of [1/16, 8)") {
    // Each reduction (x + 1 below 1, x - m above 2) must keep the argument near its centre.
    for (double lo : {1.0 / 16, 0.9999990463256836, 1.9999990463256836, 7.9999990463256836, 0.5, 1.5, 3.5}) {
        for (int shift : {20, 21, 22, 40}) {
            const double hi = std::min(lo + std::ldexp(1.0, -shift), 7.999999999999999);
            INFO("x = [" << lo << ", " << hi << "]");
            const DInterval g = gamma(DInterval(lo, hi));
            REQUIRE(encloses(g, mpfr_gamma, lo));
            REQUIRE(encloses(g, mpfr_gamma, hi));
        }
    }
}

TEST_CASE("directed + - * / sqrt are the exact roundings down and up") {
    std::mt19937_64 random(3);
    detail::rounded_arith_outward rounding;
    auto check = [&](double down, double up, const mpq_class& exact) {
        REQUIRE(mpq_class(down) <= exact);
        REQUIRE(exact <= mpq_class(up));
        // Exact results stay points, others get the two neighbours; below 2^-960, where an
        // error may underflow, a result is stepped outward on both sides (up to two ulps).
        if (abs(exact) < mpq_class(std::ldexp(1.0, -960))) return;
        if (mpq_class(down) == exact) REQUIRE(down == up);
        else REQUIRE(detail::next_up(down) == up);
    };
    for (int k = 0; k < 20000; ++k) {
        const int range = k % 3 == 0 ? 60 : 500;  // close exponents, where sums cancel, and far ones (no overflow)
        double a = random_positive(random, -range, range), b = random_positive(random, -range, range);
        if (k % 2) b = -b;
        if (k % 7 == 0) b = -a * 3;  // exact results
        check(rounding.add_down(a, b), rounding.add_up(a, b), mpq_class(a) + mpq_class(b));
        check(rounding.sub_down(a, b), rounding.sub_up(a, b), mpq_class(a) - mpq_class(b));
        check(rounding.mul_down(a, b), rounding.mul_up(a, b), mpq_class(a) * mpq_class(b));
        check(rounding.div_down(a, b), rounding.div_up(a, b), mpq_class(a) / mpq_class(b));
        const double root_down = rounding.sqrt_down(a), root_up = rounding.sqrt_up(a);
        REQUIRE(mpq_class(root_down) * mpq_class(root_down) <= mpq_class(a));
        REQUIRE(mpq_class(a) <= mpq_class(root_up) * mpq_class(root_up));
        REQUIRE((root_down == root_up || detail::next_up(root_down) == root_up));
    }
    // Underflow: a product below the smallest subnormal is not zero.
    CHECK(rounding.mul_up(0x1p-600, 0x1p-600) > 0);
    CHECK(rounding.mul_down(0x1p-600, 0x1p-600) <= 0);
    CHECK(rounding.mul_down(0x1p-600, 0x1p-600) >= -std::numeric_limits<double>::denorm_min());
    CHECK(rounding.mul_down(0.0, 5.0) == 0);
    CHECK(rounding.mul_up(0.0, 5.0) == 0);
    CHECK(rounding.add_down(0x1p-1074, -0x1p-1074) == 0);
    CHECK(rounding.mul_down(2.0, 0.5) == 1);
}
