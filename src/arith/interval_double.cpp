#include <cfenv>
#include <cmath>
#include <stdexcept>

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

DInterval exp(const DInterval& x) { return detail::enclose_exp(x); }
DInterval log(const DInterval& x) { return detail::enclose_log(x); }
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
