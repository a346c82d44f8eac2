#include "checker/formulas/chart_power.hpp"

#include <stdexcept>

namespace superpack_checker {

namespace {

// e^y for every y in the exponent interval, at one exact base e >= 0, by roots and powers when y
// is the exact point `exact`. For e > 0 both are monotone: RNDD(root(RNDD(e^|a|))) <= e^(|a|/b)
// <= RNDU(root(RNDU(e^|a|))).
Real power_at(mpfr_srcptr e, const Real& y, const ExactExponent& exact) {
    const mpfr_prec_t precision = y.precision();
    if (mpfr_zero_p(e)) {
        if (!positive(y)) throw std::domain_error("0^y with y possibly <= 0");
        return Real(precision);
    }
    if (exact.denominator == 0) return exp(y * log(outward(e, e, precision)));
    const unsigned long magnitude = static_cast<unsigned long>(exact.numerator < 0 ? -exact.numerator : exact.numerator);
    Real power(precision);
    mpfr_ptr down = power.lower_end();
    mpfr_ptr up = power.upper_end();
    mpfr_pow_ui(down, e, magnitude, MPFR_RNDD);
    mpfr_pow_ui(up, e, magnitude, MPFR_RNDU);
    if (exact.denominator > 1) {
        mpfr_rootn_ui(down, down, exact.denominator, MPFR_RNDD);
        mpfr_rootn_ui(up, up, exact.denominator, MPFR_RNDU);
    }
    return exact.numerator >= 0 ? power : integer(1, precision) / power;
}

// y as an exact small point, or none.
ExactExponent exact_of(const mpq_class& y) {
    const mpz_class& numerator = y.get_num();
    const mpz_class& denominator = y.get_den();
    if (denominator > max_root || abs(numerator) > max_power) return ExactExponent{};
    return ExactExponent{numerator.get_si(), denominator.get_ui()};
}

// e^y and e^(y-1) at one exact base e >= 0.
PowerPair powers_at(mpfr_srcptr e, const Exponent& y) {
    const mpfr_prec_t precision = y.y.precision();
    if (mpfr_zero_p(e)) {
        if (positive(y.y_minus_one)) return {power_at(e, y.y, y.exact), Real(precision)};
        if (y.exact_minus_one.denominator == 1 && y.exact_minus_one.numerator == 0)
            return {power_at(e, y.y, y.exact), integer(1, precision)};
        throw std::domain_error("0^(y-1) with y - 1 possibly <= 0");
    }
    const Real value = power_at(e, y.y, y.exact);
    return {value, value / outward(e, e, precision)};
}

}  // namespace

Exponent exponent(const mpq_class& y, mpfr_prec_t precision) {
    return Exponent{rational(y, precision), rational(y - 1, precision), exact_of(y), exact_of(y - 1)};
}

Real chart_pow_abs(const Real& x, const Exponent& y) {
    const Real a = abs(x);
    return hull(power_at(a.lo(), y.y, y.exact), power_at(a.hi(), y.y, y.exact));
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
    return hull(power_at(x.lo(), y.y, y.exact), power_at(x.hi(), y.y, y.exact));
}

}  // namespace superpack_checker
