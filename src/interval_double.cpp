#include <cfenv>
#include <cmath>
#include <stdexcept>

#include "arb_support.hpp"
#include "superpack/interval.hpp"

namespace superpack {

namespace {

// Arb works at this precision for binary64 endpoints: 11 guard bits, then one outward
// rounding to double.
constexpr slong kArbBits = 64;

// Arb's internal double heuristics assume round-to-nearest; Boost leaves the FPU in a
// directed mode between operations. Set nearest for the call, restore after.
class NearestRounding {
public:
    NearestRounding() {
        detail::sse_rounding_control::get_rounding_mode(saved_);
        detail::sse_rounding_control::to_nearest();
    }
    ~NearestRounding() { detail::sse_rounding_control::set_rounding_mode(saved_); }

private:
    detail::sse_rounding_control::rounding_mode saved_;
};

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

using ArbFunction = void (*)(arb_t, const arb_t, slong);

DInterval through_arb(const DInterval& x, ArbFunction f) {
    NearestRounding nearest;
    arb_t value;
    arb_init(value);
    to_arb(value, x);
    f(value, value, kArbBits);
    DInterval result = from_arb(value);
    arb_clear(value);
    return result;
}

double point_through_arb(double x, ArbFunction f, bool up) {
    const DInterval y = through_arb(DInterval(x), f);
    return up ? y.upper() : y.lower();
}

}  // namespace

namespace detail {
double arb_exp_down(double x) { return point_through_arb(x, arb_exp, false); }
double arb_exp_up(double x) { return point_through_arb(x, arb_exp, true); }
double arb_log_down(double x) { return point_through_arb(x, arb_log, false); }
double arb_log_up(double x) { return point_through_arb(x, arb_log, true); }
}  // namespace detail

DInterval power_of_positive(const DInterval& x, const DInterval& y) {
    NearestRounding nearest;
    arb_t base, exponent;
    arb_init(base);
    arb_init(exponent);
    to_arb(base, x);
    to_arb(exponent, y);
    arb_log(base, base, kArbBits);
    arb_mul(base, base, exponent, kArbBits);
    arb_exp(base, base, kArbBits);
    DInterval result = from_arb(base);
    arb_clear(base);
    arb_clear(exponent);
    return result;
}

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
    NearestRounding nearest;
    arb_t value;
    arb_init(value);
    arb_const_pi(value, kArbBits);
    DInterval result = from_arb(value);
    arb_clear(value);
    return result;
}

DInterval exp(const DInterval& x) { return boost::numeric::exp(x); }
DInterval log(const DInterval& x) {
    if (!(x.lower() > 0)) throw std::domain_error("log: argument not certainly positive");
    return boost::numeric::log(x);
}
DInterval sqrt(const DInterval& x) { return boost::numeric::sqrt(x); }
DInterval square(const DInterval& x) { return boost::numeric::square(x); }
DInterval abs(const DInterval& x) { return boost::numeric::abs(x); }
DInterval gamma(const DInterval& x) { return through_arb(x, detail::enclose_gamma); }
DInterval digamma(const DInterval& x) { return through_arb(x, detail::enclose_digamma); }

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
double width_upper(const DInterval& x) {
    detail::rounded_arith_opaque rounding;
    detail::sse_rounding_control::rounding_mode saved;
    rounding.get_rounding_mode(saved);
    const double width = rounding.sub_up(x.upper(), x.lower());
    rounding.set_rounding_mode(saved);
    return width;
}
DInterval from_doubles(const DInterval&, double lo, double hi) { return DInterval(lo, hi); }

void get_bounds(mpfr_t lo, mpfr_t hi, const DInterval& x) {
    mpfr_set_d(lo, x.lower(), MPFR_RNDD);
    mpfr_set_d(hi, x.upper(), MPFR_RNDU);
}

}  // namespace superpack
