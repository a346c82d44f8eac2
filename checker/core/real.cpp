#include "real.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace superpack_checker {

namespace {
std::size_t limbs_for(mpfr_prec_t precision) {
    return static_cast<std::size_t>((precision + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS);
}

// Sets `to` (of the same precision as `from`, with its own significand `storage`) to `from` by
// MPFR's custom interface: the kind (sign and class), exponent and significand limbs are
// copied as they are, which is exact and skips mpfr_set's rounding logic.
void copy_end(mpfr_ptr to, mp_limb_t* storage, mpfr_srcptr from, mpfr_prec_t precision) {
    const int kind = mpfr_custom_get_kind(from);
    const bool regular = kind == MPFR_REGULAR_KIND || kind == -MPFR_REGULAR_KIND;
    if (regular) {
        const mp_limb_t* limbs = static_cast<const mp_limb_t*>(mpfr_custom_get_significand(from));
        std::copy(limbs, limbs + limbs_for(precision), storage);  // a loop: a call to memmove cost more
    }
    mpfr_custom_init_set(to, kind, regular ? mpfr_custom_get_exp(from) : 0, precision, storage);
}
}  // namespace

void Real::attach(mpfr_prec_t precision) {
    const std::size_t limbs = limbs_for(precision);
    mp_limb_t* storage = inline_;
    std::size_t stride = inline_limbs;
    if (limbs > inline_limbs) {
        heap_.reset(new mp_limb_t[2 * limbs]);  // first, so that a bad_alloc leaves the Real as it was
        storage = heap_.get();
        stride = limbs;
    } else if (heap_) {
        heap_.reset();
    }
    precision_ = precision;
    mpfr_custom_init(storage, precision);
    mpfr_custom_init(storage + stride, precision);
    mpfr_custom_init_set(&value_->left, MPFR_ZERO_KIND, 0, precision, storage);
    mpfr_custom_init_set(&value_->right, MPFR_ZERO_KIND, 0, precision, storage + stride);
}

void Real::copy_ends(const Real& other) {
    copy_end(&value_->left, static_cast<mp_limb_t*>(mpfr_custom_get_significand(&value_->left)), other.lo(), precision_);
    copy_end(&value_->right, static_cast<mp_limb_t*>(mpfr_custom_get_significand(&value_->right)), other.hi(), precision_);
}

Real::Real(mpfr_prec_t precision) { attach(precision); }
Real::Real(const Real& other) {
    attach(other.precision_);
    copy_ends(other);
}
Real& Real::operator=(const Real& other) {
    if (this != &other) {
        if (precision_ != other.precision_) attach(other.precision_);
        copy_ends(other);
    }
    return *this;
}

namespace {
mpfr_prec_t joint(const Real& a, const Real& b) { return std::max(a.precision(), b.precision()); }

bool undefined(const Real& x) { return mpfr_nan_p(x.lo()) || mpfr_nan_p(x.hi()); }

Real undefined_real(mpfr_prec_t precision) {
    Real r(precision);
    mpfr_set_nan(r.lower_end());
    mpfr_set_nan(r.upper_end());
    return r;
}

bool zero_point(const Real& x) { return mpfr_zero_p(x.lo()) && mpfr_zero_p(x.hi()); }

// Where an interval lies: at or above 0, at or below 0, or across 0 (both ends off it). Only for
// intervals without a NaN end: mpfr_sgn calls NaN 0, so [NaN, -1] would be "at or above 0", and
// an operation choosing its ends by it would bound the wrong end (MPFI's mpfi_div, mpfi_abs and
// mpfi_sqr return NaN for a NaN end before they look at signs; the operations below do the same).
enum class Side { nonnegative, nonpositive, across };
Side side(const Real& x) {
    if (mpfr_sgn(x.lo()) >= 0) return Side::nonnegative;
    if (mpfr_sgn(x.hi()) <= 0) return Side::nonpositive;
    return Side::across;
}

// [f(lo) rounded down, f(hi) rounded up] for an increasing f given by an MPFR function.
Real increasing(const Real& x, int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t)) {
    Real r(x.precision());
    f(r.lower_end(), x.lo(), MPFR_RNDD);
    f(r.upper_end(), x.hi(), MPFR_RNDU);
    return r;
}

// x^y at one point e >= 0 of the base, for every y in the exponent interval.
Real power_at(mpfr_srcptr e, const Real& y) {
    Real point(y.precision());
    if (mpfr_zero_p(e)) {
        if (!positive(y)) throw std::domain_error("0^y with y possibly <= 0");
        return point;
    }
    // A point exponent n = 1, ..., 64 (2p at p = 2 is 4): e^n rounded down and up by MPFR,
    // as tight as the producer's products (a stored enclosure must contain the checker's).
    if (mpfr_equal_p(y.lo(), y.hi()) && mpfr_integer_p(y.lo()) && mpfr_cmp_ui(y.lo(), 1) >= 0 && mpfr_cmp_ui(y.lo(), 64) <= 0) {
        const unsigned long n = mpfr_get_ui(y.lo(), MPFR_RNDN);
        mpfr_pow_ui(point.lower_end(), e, n, MPFR_RNDD);
        mpfr_pow_ui(point.upper_end(), e, n, MPFR_RNDU);
        return point;
    }
    return exp(y * log(outward(e, e, y.precision())));
}
}  // namespace

Real integer(long n, mpfr_prec_t precision) {
    Real result(precision);
    mpfr_set_si(result.lower_end(), n, MPFR_RNDD);
    mpfr_set_si(result.upper_end(), n, MPFR_RNDU);
    return result;
}

Real rational(const mpq_class& q, mpfr_prec_t precision) {
    Real result(precision);
    mpfr_set_q(result.lower_end(), q.get_mpq_t(), MPFR_RNDD);
    mpfr_set_q(result.upper_end(), q.get_mpq_t(), MPFR_RNDU);
    return result;
}

bool exact_interval(Real& result, mpfr_srcptr lo, mpfr_srcptr hi) {
    Real candidate(result.precision());
    const bool reversed = mpfr_greater_p(lo, hi);
    const int inexact_lo = mpfr_set(candidate.lower_end(), reversed ? hi : lo, MPFR_RNDD);
    const int inexact_hi = mpfr_set(candidate.upper_end(), reversed ? lo : hi, MPFR_RNDU);
    if (inexact_lo != 0 || inexact_hi != 0) return false;
    result = candidate;
    return true;
}

Real outward(mpfr_srcptr lo, mpfr_srcptr hi, mpfr_prec_t precision) {
    if (mpfr_nan_p(lo) || mpfr_nan_p(hi)) return undefined_real(precision);  // as mpfi_interv_fr
    Real r(precision);
    const bool reversed = mpfr_greater_p(lo, hi);
    mpfr_set(r.lower_end(), reversed ? hi : lo, MPFR_RNDD);
    mpfr_set(r.upper_end(), reversed ? lo : hi, MPFR_RNDU);
    return r;
}

Real doubles(double lo, double hi, mpfr_prec_t precision) {
    // std::min(1.0, NaN) and std::max(1.0, NaN) are both 1: a NaN end would be dropped.
    if (std::isnan(lo) || std::isnan(hi)) return undefined_real(precision);  // as mpfi_interv_d
    Real r(precision);
    mpfr_set_d(r.lower_end(), std::min(lo, hi), MPFR_RNDD);
    mpfr_set_d(r.upper_end(), std::max(lo, hi), MPFR_RNDU);
    return r;
}

Real pi(mpfr_prec_t precision) {
    Real r(precision);
    mpfr_const_pi(r.lower_end(), MPFR_RNDD);
    mpfr_const_pi(r.upper_end(), MPFR_RNDU);
    return r;
}

Real operator+(const Real& a, const Real& b) {
    Real r(joint(a, b));
    mpfr_add(r.lower_end(), a.lo(), b.lo(), MPFR_RNDD);
    mpfr_add(r.upper_end(), a.hi(), b.hi(), MPFR_RNDU);
    return r;
}
Real operator-(const Real& a, const Real& b) {
    Real r(joint(a, b));
    mpfr_sub(r.lower_end(), a.lo(), b.hi(), MPFR_RNDD);
    mpfr_sub(r.upper_end(), a.hi(), b.lo(), MPFR_RNDU);
    return r;
}
Real operator*(const Real& a, const Real& b) {
    if (undefined(a) || undefined(b)) return undefined_real(joint(a, b));
    Real r(joint(a, b));
    // The point 0 times anything is 0. Elsewhere an end product 0 times an infinite end is left
    // NaN, as MPFI leaves it: it needs a factor [oo, oo], an overflow, which decides nothing.
    if (zero_point(a) || zero_point(b)) return r;
    mpfr_ptr lo = r.lower_end();
    mpfr_ptr hi = r.upper_end();
    const Side sa = side(a), sb = side(b);
    // Which ends meet at the extremes, by the sides of 0 the factors lie on.
    if (sa == Side::nonnegative && sb == Side::nonnegative) {
        mpfr_mul(lo, a.lo(), b.lo(), MPFR_RNDD);
        mpfr_mul(hi, a.hi(), b.hi(), MPFR_RNDU);
    } else if (sa == Side::nonnegative && sb == Side::nonpositive) {
        mpfr_mul(lo, a.hi(), b.lo(), MPFR_RNDD);
        mpfr_mul(hi, a.lo(), b.hi(), MPFR_RNDU);
    } else if (sa == Side::nonpositive && sb == Side::nonnegative) {
        mpfr_mul(lo, a.lo(), b.hi(), MPFR_RNDD);
        mpfr_mul(hi, a.hi(), b.lo(), MPFR_RNDU);
    } else if (sa == Side::nonpositive && sb == Side::nonpositive) {
        mpfr_mul(lo, a.hi(), b.hi(), MPFR_RNDD);
        mpfr_mul(hi, a.lo(), b.lo(), MPFR_RNDU);
    } else if (sa == Side::nonnegative) {  // b across 0
        mpfr_mul(lo, a.hi(), b.lo(), MPFR_RNDD);
        mpfr_mul(hi, a.hi(), b.hi(), MPFR_RNDU);
    } else if (sa == Side::nonpositive) {
        mpfr_mul(lo, a.lo(), b.hi(), MPFR_RNDD);
        mpfr_mul(hi, a.lo(), b.lo(), MPFR_RNDU);
    } else if (sb == Side::nonnegative) {  // a across 0
        mpfr_mul(lo, a.lo(), b.hi(), MPFR_RNDD);
        mpfr_mul(hi, a.hi(), b.hi(), MPFR_RNDU);
    } else if (sb == Side::nonpositive) {
        mpfr_mul(lo, a.hi(), b.lo(), MPFR_RNDD);
        mpfr_mul(hi, a.lo(), b.lo(), MPFR_RNDU);
    } else {  // both across 0: the smaller of the two negative products, the larger positive one
        Real other(r.precision());
        mpfr_mul(lo, a.lo(), b.hi(), MPFR_RNDD);
        mpfr_mul(other.lower_end(), a.hi(), b.lo(), MPFR_RNDD);
        mpfr_min(lo, lo, other.lo(), MPFR_RNDD);
        mpfr_mul(hi, a.lo(), b.lo(), MPFR_RNDU);
        mpfr_mul(other.upper_end(), a.hi(), b.hi(), MPFR_RNDU);
        mpfr_max(hi, hi, other.hi(), MPFR_RNDU);
    }
    return r;
}
Real operator/(const Real& a, const Real& b) {
    if (!excludes_zero(b)) throw std::domain_error("division by an interval that may contain 0");
    if (undefined(a) || undefined(b)) return undefined_real(joint(a, b));  // before side(a): see Side
    Real r(joint(a, b));
    mpfr_ptr lo = r.lower_end();
    mpfr_ptr hi = r.upper_end();
    const Side sa = side(a);
    if (positive(b)) {
        mpfr_div(lo, a.lo(), sa == Side::nonnegative ? b.hi() : b.lo(), MPFR_RNDD);
        mpfr_div(hi, a.hi(), sa == Side::nonpositive ? b.hi() : b.lo(), MPFR_RNDU);
    } else {
        mpfr_div(lo, a.hi(), sa == Side::nonpositive ? b.lo() : b.hi(), MPFR_RNDD);
        mpfr_div(hi, a.lo(), sa == Side::nonnegative ? b.lo() : b.hi(), MPFR_RNDU);
    }
    return r;
}
Real operator-(const Real& a) {
    Real r(a.precision());
    mpfr_neg(r.lower_end(), a.hi(), MPFR_RNDD);  // exact
    mpfr_neg(r.upper_end(), a.lo(), MPFR_RNDU);
    return r;
}
Real operator*(long n, const Real& a) { return integer(n, a.precision()) * a; }

Real exp(const Real& x) { return increasing(x, mpfr_exp); }
Real log(const Real& x) {
    if (!positive(x)) throw std::domain_error("log of an interval that may be <= 0");
    return increasing(x, mpfr_log);
}
Real expm1(const Real& x) { return increasing(x, mpfr_expm1); }
Real log1p(const Real& x) {
    if (!positive(x + integer(1, x.precision()))) throw std::domain_error("log1p of an interval that may be <= -1");
    return increasing(x, mpfr_log1p);
}
Real abs(const Real& x) {
    if (undefined(x)) return undefined_real(x.precision());  // before side(x): see Side
    switch (side(x)) {
        case Side::nonnegative: return x;
        case Side::nonpositive: return -x;
        case Side::across: break;
    }
    Real r(x.precision());
    mpfr_set_zero(r.lower_end(), 1);
    mpfr_neg(r.upper_end(), x.lo(), MPFR_RNDU);
    mpfr_max(r.upper_end(), r.upper_end(), x.hi(), MPFR_RNDU);
    return r;
}
Real square(const Real& x) {
    if (undefined(x)) return undefined_real(x.precision());  // before side(x): see Side
    if (side(x) != Side::across) {
        const Real a = abs(x);
        Real r(x.precision());
        mpfr_sqr(r.lower_end(), a.lo(), MPFR_RNDD);
        mpfr_sqr(r.upper_end(), a.hi(), MPFR_RNDU);
        return r;
    }
    Real r(x.precision());
    mpfr_set_zero(r.lower_end(), 1);
    mpfr_sqr(r.upper_end(), mpfr_cmpabs(x.lo(), x.hi()) > 0 ? x.lo() : x.hi(), MPFR_RNDU);
    return r;
}
Real sqrt(const Real& x) {
    if (mpfr_sgn(x.lo()) < 0) throw std::domain_error("sqrt of an interval that may be < 0");
    return increasing(x, mpfr_sqrt);
}

Real pow_abs(const Real& x, const Real& y) {
    if (mpfr_zero_p(y.lo()) && mpfr_zero_p(y.hi())) return integer(1, x.precision());
    // y = 0 is allowed where |x| > 0 (x^0 = 1); 0^y needs y > 0 (power_at checks it).
    if (mpfr_sgn(y.lo()) < 0) throw std::domain_error("pow_abs: exponent may be < 0");
    const Real a = abs(x);
    return hull(power_at(a.lo(), y), power_at(a.hi(), y));
}

Real pow_signed(const Real& x, const Real& y) {
    if (positive(x)) return pow_abs(x, y);
    if (negative(x)) return -pow_abs(x, y);
    const Real magnitude = upper_point(pow_abs(x, y));
    return hull(-magnitude, magnitude);
}

Real gamma(const Real& x) {
    if (!positive(x)) throw std::domain_error("gamma of an interval that may be <= 0");
    const mpfr_prec_t precision = x.precision();
    // Gamma is convex on (0, oo) and Gamma' = Gamma psi with psi (digamma) increasing, so the
    // sign of psi at the ends decides monotonicity, and the maximum is at an end.
    Real gamma_lo(precision), gamma_hi(precision), psi_lo(precision), psi_hi(precision);
    auto at = [&](Real& result, int (*function)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t), mpfr_srcptr point) {
        function(result.lower_end(), point, MPFR_RNDD);
        function(result.upper_end(), point, MPFR_RNDU);
    };
    at(gamma_lo, mpfr_gamma, x.lo());
    at(gamma_hi, mpfr_gamma, x.hi());
    at(psi_lo, mpfr_digamma, x.lo());
    at(psi_hi, mpfr_digamma, x.hi());
    if (mpfr_sgn(psi_lo.lo()) >= 0) return hull(lower_point(gamma_lo), upper_point(gamma_hi));  // increasing
    if (mpfr_sgn(psi_hi.hi()) <= 0) return hull(lower_point(gamma_hi), upper_point(gamma_lo));  // decreasing
    // x holds the minimum. Mean value: Gamma(t) = Gamma(a) + Gamma(xi) psi(xi) (t - a) with
    // Gamma(xi) in (0, M], M the larger end value, psi(xi) in [psi(a), psi(b)], t - a in [0, b - a].
    const Real top = upper_point(hull(gamma_lo, gamma_hi));
    const Real zero(precision);
    const Real spread = hull(zero, upper_point(x) - lower_point(x));
    const Real range = gamma_lo + hull(zero, top) * hull(psi_lo, psi_hi) * spread;
    return hull(lower_point(range), top);
}

Real hull(const Real& a, const Real& b) {
    // A NaN end spreads, where MPFR's min and max would drop it: what is undefined stays so.
    if (undefined(a) || undefined(b)) return undefined_real(joint(a, b));
    Real r(joint(a, b));
    mpfr_min(r.lower_end(), a.lo(), b.lo(), MPFR_RNDD);
    mpfr_max(r.upper_end(), a.hi(), b.hi(), MPFR_RNDU);
    return r;
}
Real lower_point(const Real& x) { return outward(x.lo(), x.lo(), x.precision()); }
Real upper_point(const Real& x) { return outward(x.hi(), x.hi(), x.precision()); }
Real midpoint(const Real& x) {
    mpfr_t center;
    mpfr_init2(center, x.precision());
    mpfi_mid(center, x.get());
    // mpfi_mid rounds to nearest; clamp so that the point lies in x whatever happened.
    if (mpfr_cmp(center, x.lo()) < 0) mpfr_set(center, x.lo(), MPFR_RNDN);
    if (mpfr_cmp(center, x.hi()) > 0) mpfr_set(center, x.hi(), MPFR_RNDN);
    Real r = outward(center, center, x.precision());
    mpfr_clear(center);
    return r;
}
bool intersect(Real& result, const Real& a, const Real& b) {
    if (mpfr_cmp(a.hi(), b.lo()) < 0 || mpfr_cmp(b.hi(), a.lo()) < 0) return false;
    result = outward(mpfr_cmp(a.lo(), b.lo()) > 0 ? a.lo() : b.lo(), mpfr_cmp(a.hi(), b.hi()) < 0 ? a.hi() : b.hi(),
                     joint(a, b));
    return true;
}

bool positive(const Real& x) { return mpfr_sgn(x.lo()) > 0; }
bool negative(const Real& x) { return mpfr_sgn(x.hi()) < 0; }
bool excludes_zero(const Real& x) { return positive(x) || negative(x); }
// The mpfr_*_p comparisons are false when an end is NaN (mpfr_cmp would call it equal), so
// that no predicate can hold for an interval that arithmetic has left undefined.
bool less(const Real& a, const Real& b) { return mpfr_less_p(a.hi(), b.lo()) != 0; }
bool subset(const Real& inner, const Real& outer) {
    return mpfr_lessequal_p(outer.lo(), inner.lo()) && mpfr_lessequal_p(inner.hi(), outer.hi());
}
bool interior_subset(const Real& inner, const Real& outer) {
    return mpfr_less_p(outer.lo(), inner.lo()) && mpfr_less_p(inner.hi(), outer.hi());
}
Width::Width(double x) {
    mpfr_init2(value_, 53);
    mpfr_set_d(value_, x, MPFR_RNDU);
}
Width::Width(const Width& other) {
    mpfr_init2(value_, 53);
    mpfr_set(value_, other.value_, MPFR_RNDU);
}
Width& Width::operator=(const Width& other) {
    mpfr_set(value_, other.value_, MPFR_RNDU);
    return *this;
}
Width::~Width() { mpfr_clear(value_); }

Width width(const Real& x) {
    Width result;
    mpfr_sub(result.get(), x.hi(), x.lo(), MPFR_RNDU);
    return result;
}
Width operator+(const Width& a, const Width& b) {
    Width result;
    mpfr_add(result.get(), a.get(), b.get(), MPFR_RNDU);
    return result;
}
Width operator*(double factor, const Width& w) {
    Width result;
    mpfr_mul_d(result.get(), w.get(), factor, MPFR_RNDU);
    return result;
}
Width scaled(const Width& w, long exponent) {
    Width result;
    mpfr_mul_2si(result.get(), w.get(), exponent, MPFR_RNDU);
    return result;
}
Width magnitude(const Real& x) {
    Width result(1), end;
    for (mpfr_srcptr bound : {x.lo(), x.hi()}) {
        mpfr_abs(end.get(), bound, MPFR_RNDU);
        mpfr_max(result.get(), result.get(), end.get(), MPFR_RNDU);
    }
    return result;
}
bool operator<(const Width& a, const Width& b) { return mpfr_less_p(a.get(), b.get()) != 0; }
bool operator<=(const Width& a, const Width& b) { return mpfr_lessequal_p(a.get(), b.get()) != 0; }
bool operator>(const Width& a, const Width& b) { return mpfr_greater_p(a.get(), b.get()) != 0; }
bool operator>=(const Width& a, const Width& b) { return mpfr_greaterequal_p(a.get(), b.get()) != 0; }
bool operator==(const Width& a, const Width& b) { return mpfr_equal_p(a.get(), b.get()) != 0; }
std::ostream& operator<<(std::ostream& out, const Width& w) {
    char digits[64];
    mpfr_snprintf(digits, sizeof digits, "%.6RUg", w.get());
    return out << digits;
}

double middle(const Real& x) {
    mpfr_t center;
    mpfr_init2(center, x.precision());
    mpfi_mid(center, x.get());
    const double result = mpfr_get_d(center, MPFR_RNDN);
    mpfr_clear(center);
    return result;
}

std::string text(const Real& x) {
    char lo[64], hi[64];
    mpfr_snprintf(lo, sizeof lo, "%.20RDg", x.lo());
    mpfr_snprintf(hi, sizeof hi, "%.20RUg", x.hi());
    return std::string("[") + lo + ", " + hi + "]";
}

}  // namespace superpack_checker
