// The checker's chart powers (checker/formulas/chart_power.cpp) at exact rational exponents a/b, taken as
// the b-th root of e^|a| with outward rounding instead of exp(y log e). Each enclosure is compared
// with MPFI's exp(y log e) at 512 bits (another algorithm): the two must meet, and the root path
// must be tight (a few ulps at 128 bits). Bases run from the smallest subnormal to 1e30; where
// the power is a dyadic number it must be exact; exponents of large numerator or denominator go
// by exp and log.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "checker/formulas/chart_power.hpp"

namespace {

using superpack_checker::Real;

constexpr mpfr_prec_t bits = 128;

Real point(double e, mpfr_prec_t precision) { return superpack_checker::doubles(e, e, precision); }

// log2 of hi / lo - 1, as a count of ulps at `bits` (0 for a point).
double relative_width_ulps(const Real& x) {
    mpfr_t w;
    mpfr_init2(w, 256);  // enough to see a few ulps at 128 bits
    mpfr_div(w, x.hi(), x.lo(), MPFR_RNDU);
    mpfr_sub_ui(w, w, 1, MPFR_RNDU);
    const double ulps = mpfr_get_d(w, MPFR_RNDU) * std::ldexp(1.0, static_cast<int>(bits));
    mpfr_clear(w);
    return ulps;
}

}  // namespace

TEST_CASE("checker powers at exact exponents a/b: tight, exact at dyadic values, and within exp(y log e) at 512 bits") {
    const std::vector<mpq_class> exponents{mpq_class(6, 5), mpq_class(1, 5),  mpq_class(5, 6), mpq_class(-1, 6),
                                           mpq_class(4),    mpq_class(3),     mpq_class(1, 4), mpq_class(-3, 4),
                                           mpq_class(3, 2), mpq_class(2, 3),  mpq_class(-1, 3), mpq_class(5, 2),
                                           mpq_class(-3, 5), mpq_class(1, 64), mpq_class(256)};
    const std::vector<double> bases{0x1p-1074, 0x1p-1022, 1e-300, 1e-9, 0.1, 0.5, 0.9999999999999999, 1, 1.5, 2, 3, 1e30};
    for (const mpq_class& y : exponents) {
        const superpack_checker::Exponent exponent = superpack_checker::exponent(y, bits);
        REQUIRE(exponent.exact.denominator == y.get_den().get_ui());
        for (const double e : bases) {
            INFO("e = " << e << ", y = " << y.get_str());
            const Real value = superpack_checker::chart_pow_positive(point(e, bits), exponent);
            Real reference = exp(superpack_checker::rational(y, 512) * log(point(e, 512)));
            Real meet(512);
            CHECK(superpack_checker::intersect(meet, value, reference));
            CHECK(relative_width_ulps(value) <= 4);
        }
    }
    // Dyadic values are exact: 32^(6/5) = 64, 16^(-1/4) = 1/2, 8^(2/3) = 4, 2^(-1/6) is not.
    const auto exact_at = [](double e, const mpq_class& y, double expected) {
        const Real value = superpack_checker::chart_pow_positive(point(e, bits), superpack_checker::exponent(y, bits));
        return mpfr_cmp_d(value.lo(), expected) == 0 && mpfr_cmp_d(value.hi(), expected) == 0;
    };
    CHECK(exact_at(32, mpq_class(6, 5), 64));
    CHECK(exact_at(16, mpq_class(-1, 4), 0.5));
    CHECK(exact_at(8, mpq_class(2, 3), 4));
    CHECK(exact_at(0x1p-1000, mpq_class(1, 5), 0x1p-200));
    CHECK_FALSE(exact_at(2, mpq_class(-1, 6), std::pow(2.0, -1.0 / 6)));
    // Beyond the limits the exponent is not exact and the power goes by exp and log.
    CHECK(superpack_checker::exponent(mpq_class(1, superpack_checker::max_root + 1), bits).exact.denominator == 0);
    CHECK(superpack_checker::exponent(mpq_class(superpack_checker::max_power + 1), bits).exact.denominator == 0);
}

TEST_CASE("checker |x|^y across 0 at exact exponents: [0, max] for y > 0, and the kernel's sign") {
    const superpack_checker::Exponent y = superpack_checker::exponent(mpq_class(6, 5), bits);
    const Real x = superpack_checker::doubles(-0.5, 1, bits);
    const Real value = superpack_checker::chart_pow_abs(x, y);
    CHECK(mpfr_zero_p(value.lo()));
    CHECK(mpfr_cmp_d(value.hi(), 1) == 0);
    const superpack_checker::PowerPair pair = superpack_checker::chart_pow_abs_pair(x, y);
    // sign(x) |x|^(1/5) over [-0.5, 1]: within [-1, 1], below 0 somewhere and reaching 1.
    CHECK(mpfr_cmp_d(pair.kernel.hi(), 1) == 0);
    CHECK(mpfr_cmp_d(pair.kernel.lo(), -1) >= 0);
    CHECK(mpfr_sgn(pair.kernel.lo()) < 0);
}
