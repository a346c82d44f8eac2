#include <cfenv>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "arith/arb_support.hpp"
#include "arith/elementary_double.hpp"
#include "superpack/arith/interval.hpp"
#include "superpack/arith/mpfr_bounds.hpp"

namespace superpack {

namespace {

// Arb works at this precision for binary64 endpoints: 11 guard bits, then one outward
// rounding to double.
constexpr slong kArbBits = 64;

void to_arb(arb_t result, const DInterval& x) {
    arf_t lo, hi;
    arf_init(lo);
    arf_init(hi);
    arf_set_d(lo, x.lower());
    arf_set_d(hi, x.upper());
    arb_set_interval_arf(result, lo, hi, kArbBits);
    arf_clear(lo);
    arf_clear(hi);
}

}  // namespace

namespace detail {

DInterval from_arb(const arb_t x) {
    if (!arb_is_finite(x)) return DInterval::whole();
    arf_t lo, hi;
    arf_init(lo);
    arf_init(hi);
    detail::lower_exact(lo, x);
    detail::upper_exact(hi, x);
    const double down = arf_get_d(lo, ARF_RND_FLOOR);
    const double up = arf_get_d(hi, ARF_RND_CEIL);
    arf_clear(lo);
    arf_clear(hi);
    return DInterval(down, up);
}

DInterval through_arb(const DInterval& x, ArbFunction f) {
    arb_t value;
    arb_init(value);
    to_arb(value, x);
    f(value, value, kArbBits);
    DInterval result = from_arb(value);
    arb_clear(value);
    return result;
}

}  // namespace detail

DInterval power_of_positive(const DInterval& x, const DInterval& y) { return exp(y * log(x)); }

DInterval DoubleField::rational(const Rational& q) const {
    mpfr_t bound;
    mpfr_init2(bound, 53);
    mpfr_set_q(bound, q.get_mpq_t(), MPFR_RNDD);
    const double lo = mpfr_get_d(bound, MPFR_RNDD);
    mpfr_set_q(bound, q.get_mpq_t(), MPFR_RNDU);
    const double hi = mpfr_get_d(bound, MPFR_RNDU);
    mpfr_clear(bound);
    return DInterval(lo, hi);
}

DInterval DoubleField::pi() const {
    arb_t value;
    arb_init(value);
    arb_const_pi(value, kArbBits);
    DInterval result = detail::from_arb(value);
    arb_clear(value);
    return result;
}

namespace {

// log(1 + x) at a point x > -1, with a relative error of a few units in the last place
// (NOTES.md 1.2). Near 0, log(1 + x) through a rounded 1 + x would keep only an absolute
// accuracy of 2^-53, which is what the contact equations of C0 and C1 lose at large p.
DInterval log1p_at(double x) {
    if (std::fabs(x) <= 0.0625) {
        // 2 atanh z with z = x / (2 + x), |z| <= 1/31: 2z (1 + z^2/3 + ... + z^10/11 + z^12 R)
        // with 0 <= R <= 1 / (13 (1 - z^2)) < 1/12, all in outward-rounded interval arithmetic.
        const DInterval point(x), one(1.0);
        const DInterval z = point / (DInterval(2.0) + point);
        const DInterval z2 = square(z);
        DInterval series = z2 * DInterval(0.0, 1.0 / 12);  // R < 0.078 < fl(1/12)
        for (const int denominator : {11, 9, 7, 5, 3}) series = z2 * (one / DInterval(denominator) + series);
        return DInterval(2.0) * z * (one + series);
    }
    // 1 + x = y + e exactly (TwoSum), so log(1 + x) = log y + log(1 + e/y) with |e/y| <= 2^-53,
    // and z - z^2 <= log(1 + z) <= z for |z| <= 1/2. Here |log y| > 0.06, where log has a
    // relative error of a few ulps.
    const double y = 1 + x;
    const double one_part = y - x;
    const double x_part = y - one_part;
    const double e = (1 - one_part) + (x - x_part);
    const DInterval ratio = DInterval(e) / DInterval(y);
    return log(DInterval(y)) + hull(ratio - square(ratio), ratio);
}

// exp(x) - 1 at a point x, with a relative error of a few ulps: for |x| <= 1/2 the series
// x (1 + x/2! + ... + x^19/20! + x^20 R), |R| <= sum_j |x|^j/(21 + j)! < 2.01e-20, in outward
// interval arithmetic; beyond, exp(x) - 1, which is at least 0.39 in size there.
DInterval expm1_at(double x) {
    if (std::fabs(x) > 0.5) return exp(DInterval(x)) - DInterval(1.0);
    static const std::vector<DInterval> inverse_factorials = [] {
        std::vector<DInterval> table;  // 1/(k + 1)! for k = 0..19; (k + 1)! <= 20! is a double
        double factorial = 1;
        for (int k = 1; k <= 20; ++k) {
            factorial *= k;
            table.push_back(DInterval(1.0) / DInterval(factorial));
        }
        return table;
    }();
    const DInterval point(x);
    DInterval series(-3e-20, 3e-20);
    for (int k = 19; k >= 0; --k) series = inverse_factorials[k] + point * series;
    return point * series;
}

}  // namespace

DInterval exp(const DInterval& x) { return detail::enclose_exp(x); }
DInterval log(const DInterval& x) { return detail::enclose_log(x); }
// Increasing: the lower end's value rounded down and the upper end's rounded up.
DInterval expm1(const DInterval& x) {
    const DInterval low = expm1_at(x.lower());
    if (x.lower() == x.upper()) return low;
    return DInterval(low.lower(), expm1_at(x.upper()).upper());
}
DInterval log1p(const DInterval& x) {
    if (!(x.lower() > -1)) throw std::domain_error("log1p: argument not certainly > -1");
    const DInterval low = log1p_at(x.lower());
    if (x.lower() == x.upper()) return low;
    return DInterval(low.lower(), log1p_at(x.upper()).upper());
}
DInterval sqrt(const DInterval& x) { return boost::numeric::sqrt(x); }
DInterval square(const DInterval& x) { return boost::numeric::square(x); }
DInterval abs(const DInterval& x) { return boost::numeric::abs(x); }
// A narrow argument in [1/16, 8): the series is as tight as the endpoint hull and needs no
// library call; anything else goes to Arb's monotonicity-aware evaluation.
DInterval gamma(const DInterval& x) {
    if (detail::gamma_series_applies(x)) return detail::enclose_gamma_series(x);
    return detail::through_arb(x, detail::enclose_gamma);
}
DInterval digamma(const DInterval& x) { return detail::through_arb(x, detail::enclose_digamma); }

DInterval lower_point(const DInterval& x) { return DInterval(x.lower()); }
DInterval upper_point(const DInterval& x) { return DInterval(x.upper()); }
DInterval midpoint(const DInterval& x) { return DInterval(boost::numeric::median(x)); }
DInterval hull(const DInterval& a, const DInterval& b) { return boost::numeric::hull(a, b); }
bool intersect(DInterval& result, const DInterval& a, const DInterval& b) {
    if (a.upper() < b.lower() || b.upper() < a.lower()) return false;
    result = DInterval(std::max(a.lower(), b.lower()), std::min(a.upper(), b.upper()));
    return true;
}

bool certainly_positive(const DInterval& x) { return x.lower() > 0; }
bool certainly_negative(const DInterval& x) { return x.upper() < 0; }
bool certainly_nonnegative(const DInterval& x) { return x.lower() >= 0; }
bool certainly_less(const DInterval& a, const DInterval& b) { return a.upper() < b.lower(); }
bool contains_zero(const DInterval& x) { return x.lower() <= 0 && 0 <= x.upper(); }
bool contains(const DInterval& outer, const DInterval& inner) {
    return outer.lower() <= inner.lower() && inner.upper() <= outer.upper();
}
bool interior_contains(const DInterval& outer, const DInterval& inner) {
    return outer.lower() < inner.lower() && inner.upper() < outer.upper();
}

double mid_double(const DInterval& x) { return boost::numeric::median(x); }
double width_upper(const DInterval& x) { return detail::rounded_arith_outward().sub_up(x.upper(), x.lower()); }
DInterval from_doubles(const DInterval&, double lo, double hi) { return DInterval(lo, hi); }

void get_bounds(mpfr_t lo, mpfr_t hi, const DInterval& x) {
    mpfr_set_d(lo, x.lower(), MPFR_RNDD);
    mpfr_set_d(hi, x.upper(), MPFR_RNDU);
}

}  // namespace superpack
