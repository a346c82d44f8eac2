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

// log(1 + x) for x > -1 with a relative error of a few units in the last place (NOTES.md 1.2).
// Near 0, log(1 + x) through a rounded 1 + x would keep only an absolute accuracy of 2^-53,
// which is what the contact equations of C0 and C1 lose at large p.
constexpr double kLog1pSeriesLimit = 0.0625;

// 2 atanh z with z = x / (2 + x), |z| <= 1/31 for |x| <= 1/16: 2z (1 + z^2/3 + ... + z^10/11 +
// z^12 R) with 0 <= R <= 1 / (13 (1 - z^2)) < 1/12, all in outward-rounded interval arithmetic.
// Every step encloses its exact result, so a whole (narrow) interval x can be evaluated at once.
DInterval log1p_series(const DInterval& x) {
    // The reciprocals 1/11, 1/9, ..., 1/3 are enclosed once: dividing at each call cost as much
    // as the rest of the series.
    static const std::vector<DInterval> reciprocals = [] {
        std::vector<DInterval> table;
        for (const int denominator : {11, 9, 7, 5, 3}) table.push_back(DInterval(1.0) / DInterval(denominator));
        return table;
    }();
    const DInterval z = x / (DInterval(2.0) + x);
    const DInterval z2 = square(z);
    DInterval series = z2 * DInterval(0.0, 1.0 / 12);  // R < 0.078 < fl(1/12)
    for (const DInterval& reciprocal : reciprocals) series = z2 * (reciprocal + series);
    return DInterval(2.0) * z * (DInterval(1.0) + series);
}

// 1 + x = y + e exactly (TwoSum), so log(1 + x) = log y + log(1 + e/y) with |e/y| <= 2^-53, and
// z - z^2 <= log(1 + z) <= z for |z| <= 1/2: the correction of x, enclosed.
struct RoundedOnePlus {
    double y;
    DInterval correction;
};
RoundedOnePlus rounded_one_plus(double x) {
    const double y = 1 + x;
    const double one_part = y - x;
    const double x_part = y - one_part;
    const double e = (1 - one_part) + (x - x_part);
    const DInterval ratio = DInterval(e) / DInterval(y);
    return {y, hull(ratio - square(ratio), ratio)};
}

// Beyond the series' range |log y| > 0.06, where log has a relative error of a few ulps.
DInterval log1p_at(double x) {
    if (std::fabs(x) <= kLog1pSeriesLimit) return log1p_series(DInterval(x));
    const RoundedOnePlus sum = rounded_one_plus(x);
    return log(DInterval(sum.y)) + sum.correction;
}

// exp(x) - 1 with a relative error of a few ulps for |x| <= 1/2: the series
// x (1 + x/2! + ... + x^(n-1)/n! + x^n R) in outward interval arithmetic, where
// |R| <= sum_j |x|^j/(n + 1 + j)! <= 1/((n + 1)! (1 - |x|/(n + 2))) <= 1.25/(n + 1)! for n >= 1;
// n is the first term count with |x|^n/(n + 1)! <= 2^-60, at most 20 (a guess: any n is
// sound, and a small x, as at large p, needs few terms). Every step encloses its exact result,
// so a whole (narrow) interval x can be evaluated at once.
constexpr double kExpm1SeriesLimit = 0.5;
DInterval expm1_series(const DInterval& x) {
    constexpr int kMostTerms = 20;
    static const std::vector<DInterval> inverse_factorials = [] {
        std::vector<DInterval> table;  // 1/(k + 1)! for k = 0..20; (k + 1)! <= 21! is a double
        double factorial = 1;
        for (int k = 1; k <= kMostTerms + 1; ++k) {
            factorial *= k;
            table.push_back(DInterval(1.0) / DInterval(factorial));
        }
        return table;
    }();
    const double size = std::max(std::fabs(x.lower()), std::fabs(x.upper()));
    int terms = 1;
    for (double term = size / 2; terms < kMostTerms && term > 0x1p-60; ++terms) term *= size / (terms + 2);
    const double remainder = (DInterval(1.25) * inverse_factorials[terms]).upper();
    DInterval series(-remainder, remainder);
    for (int k = terms - 1; k >= 0; --k) series = inverse_factorials[k] + x * series;
    return x * series;
}

// Beyond 1/2, exp(x) - 1, which is at least 0.39 in size there.
DInterval expm1_at(double x) {
    if (std::fabs(x) > kExpm1SeriesLimit) return exp(DInterval(x)) - DInterval(1.0);
    return expm1_series(DInterval(x));
}

}  // namespace

DInterval exp(const DInterval& x) { return detail::enclose_exp(x); }
DInterval log(const DInterval& x) { return detail::enclose_log(x); }
// Increasing: the lower end's value rounded down and the upper end's rounded up, except that a
// narrow interval inside the series' range is evaluated as a whole (one evaluation, not two).
DInterval expm1(const DInterval& x) {
    if (x.lower() != x.upper() && x.upper() - x.lower() <= 0x1p-20 && std::fabs(x.lower()) <= kExpm1SeriesLimit &&
        std::fabs(x.upper()) <= kExpm1SeriesLimit)
        return expm1_series(x);
    const DInterval low = expm1_at(x.lower());
    if (x.lower() == x.upper()) return low;
    return DInterval(low.lower(), expm1_at(x.upper()).upper());
}
// A narrow interval on one side of the series' limit is evaluated as a whole, which costs one
// evaluation instead of two (Newton's boxes); log1p is increasing, so each end's value also
// bounds the whole range.
DInterval log1p(const DInterval& x) {
    if (!(x.lower() > -1)) throw std::domain_error("log1p: argument not certainly > -1");
    if (x.lower() != x.upper() && x.upper() - x.lower() <= 0x1p-20) {
        if (std::fabs(x.lower()) <= kLog1pSeriesLimit && std::fabs(x.upper()) <= kLog1pSeriesLimit)
            return log1p_series(x);
        if ((x.lower() > kLog1pSeriesLimit || x.upper() < -kLog1pSeriesLimit)) {
            // log1p(a) = log(y_a) + c_a >= (the lower end of log [y_a, y_b]) + c_a, and likewise at b.
            const RoundedOnePlus low = rounded_one_plus(x.lower()), high = rounded_one_plus(x.upper());
            const DInterval logarithm = log(DInterval(low.y, high.y));
            return DInterval((DInterval(logarithm.lower()) + low.correction).lower(),
                             (DInterval(logarithm.upper()) + high.correction).upper());
        }
    }
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
