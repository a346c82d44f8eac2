#include "checker/chart_power.hpp"

#include <stdexcept>

namespace superpack_checker {

namespace {

// The largest |4y| of a point exponent y = k/4 taken by roots and products instead of
// exp(y log x) (exp and log are the dearest operations of the replay, as they were the
// producer's).
constexpr long max_quarter_exponent = 256;

// e^n for an integer n, e > 0 exact: MPFR's pow_ui rounded both ways, inverted for n < 0.
Real integer_power(const Real& e, long n) {
    const mpfr_prec_t precision = e.precision();
    if (n == 0) return integer(1, precision);
    const unsigned long m = static_cast<unsigned long>(n < 0 ? -n : n);
    mpfr_t down, up;
    mpfr_inits2(precision, down, up, static_cast<mpfr_ptr>(nullptr));
    mpfr_pow_ui(down, e.lo(), m, MPFR_RNDD);
    mpfr_pow_ui(up, e.lo(), m, MPFR_RNDU);
    Real power(precision);
    mpfi_interv_fr(power.get(), down, up);
    mpfr_clears(down, up, static_cast<mpfr_ptr>(nullptr));
    return n > 0 ? power : integer(1, precision) / power;
}

Real square_root(const Real& x) {
    Real r(x.precision());
    mpfi_sqrt(r.get(), x.get());
    return r;
}

// 4y when y is a point k/4 with |k| <= max_quarter_exponent, else no_quarters.
long quarters_of(const Real& y) {
    if (!mpfr_equal_p(y.lo(), y.hi())) return no_quarters;
    mpfr_t quarters;
    mpfr_init2(quarters, y.precision());
    mpfr_mul_2ui(quarters, y.lo(), 2, MPFR_RNDN);  // exact
    const bool small = mpfr_integer_p(quarters) && mpfr_cmpabs_ui(quarters, max_quarter_exponent) <= 0;
    const long k = small ? mpfr_get_si(quarters, MPFR_RNDN) : no_quarters;
    mpfr_clear(quarters);
    return k;
}

// e^y for every y in the exponent interval, at one exact base e >= 0 (4y = quarters if that is
// not no_quarters).
Real power_at(mpfr_srcptr e, const Real& y, long quarters) {
    const mpfr_prec_t precision = y.precision();
    if (mpfr_zero_p(e)) {
        if (!positive(y)) throw std::domain_error("0^y with y possibly <= 0");
        return Real(precision);
    }
    Real base(precision);
    mpfi_set_fr(base.get(), e);
    if (quarters == no_quarters) return exp(y * log(base));
    // y = n + r/4 with r in 0..3: e^n times sqrt(e) and sqrt(sqrt(e)) as r asks.
    const long n = (quarters >= 0 ? quarters : quarters - 3) / 4, r = quarters - 4 * n;
    const Real result = integer_power(base, n);
    if (r == 0) return result;
    const Real root = square_root(base);
    if (r == 2) return result * root;
    const Real fourth = square_root(root);
    return r == 1 ? result * fourth : result * (root * fourth);
}

// e^y and e^(y-1) at one exact base e >= 0.
PowerPair powers_at(mpfr_srcptr e, const Exponent& y) {
    const mpfr_prec_t precision = y.y.precision();
    if (mpfr_zero_p(e)) {
        if (positive(y.y_minus_one)) return {power_at(e, y.y, y.quarters), Real(precision)};
        if (y.quarters_minus_one == 0) return {power_at(e, y.y, y.quarters), integer(1, precision)};
        throw std::domain_error("0^(y-1) with y - 1 possibly <= 0");
    }
    Real base(precision);
    mpfi_set_fr(base.get(), e);
    const Real value = power_at(e, y.y, y.quarters);
    return {value, value / base};
}

}  // namespace

Exponent exponent(const mpq_class& y, mpfr_prec_t precision) {
    Exponent e{rational(y, precision), rational(y - 1, precision), no_quarters, no_quarters};
    e.quarters = quarters_of(e.y);
    e.quarters_minus_one = quarters_of(e.y_minus_one);
    return e;
}

Real chart_pow_abs(const Real& x, const Exponent& y) {
    const Real a = abs(x);
    return hull(power_at(a.lo(), y.y, y.quarters), power_at(a.hi(), y.y, y.quarters));
}

PowerPair chart_pow_abs_pair(const Real& x, const Exponent& y) {
    const Real a = abs(x);
    const PowerPair low = powers_at(a.lo(), y), high = powers_at(a.hi(), y);
    const Real value = hull(low.value, high.value), magnitude = hull(low.kernel, high.kernel);
    if (positive(x)) return {value, magnitude};
    if (negative(x)) return {value, -magnitude};
    if (mpfr_sgn(y.y_minus_one.lo()) < 0) throw std::domain_error("sign(x) |x|^y with x possibly 0 and y possibly < 0 is unbounded");
    const Real top = upper_point(magnitude);
    return {value, hull(-top, top)};
}

PowerPair chart_pow_positive_pair(const Real& x, const Exponent& y) {
    if (!positive(x)) throw std::domain_error("x^y with x possibly <= 0, on a base that must be a sum in [1, 3]");
    const PowerPair low = powers_at(x.lo(), y), high = powers_at(x.hi(), y);
    return {hull(low.value, high.value), hull(low.kernel, high.kernel)};
}

Real chart_pow_positive(const Real& x, const Exponent& y) {
    if (!positive(x)) throw std::domain_error("x^y with x possibly <= 0, on a base that must be a sum in [1, 3]");
    return hull(power_at(x.lo(), y.y, y.quarters), power_at(x.hi(), y.y, y.quarters));
}

}  // namespace superpack_checker
