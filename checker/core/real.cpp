#include "real.hpp"

#include <algorithm>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace superpack_checker {

Real::Real(mpfr_prec_t precision) : precision_(precision) {
    mpfi_init2(value_, precision);
    mpfi_set_si(value_, 0);
}
Real::Real(const Real& other) : precision_(other.precision_) {
    mpfi_init2(value_, precision_);
    mpfi_set(value_, other.value_);
}
Real::Real(Real&& other) noexcept : Real(other) {}
Real& Real::operator=(const Real& other) {
    if (this != &other) {
        mpfi_set_prec(value_, other.precision_);
        precision_ = other.precision_;
        mpfi_set(value_, other.value_);
    }
    return *this;
}
Real& Real::operator=(Real&& other) noexcept { return *this = static_cast<const Real&>(other); }
Real::~Real() { mpfi_clear(value_); }

namespace {
mpfr_prec_t joint(const Real& a, const Real& b) { return std::max(a.precision(), b.precision()); }

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
        mpfr_t down, up;
        mpfr_inits2(y.precision(), down, up, static_cast<mpfr_ptr>(nullptr));
        mpfr_pow_ui(down, e, n, MPFR_RNDD);
        mpfr_pow_ui(up, e, n, MPFR_RNDU);
        mpfi_interv_fr(point.get(), down, up);
        mpfr_clears(down, up, static_cast<mpfr_ptr>(nullptr));
        return point;
    }
    mpfi_set_fr(point.get(), e);
    return exp(y * log(point));
}
}  // namespace

Real integer(long n, mpfr_prec_t precision) {
    Real result(precision);
    mpfi_set_si(result.get(), n);
    return result;
}

Real rational(const mpq_class& q, mpfr_prec_t precision) {
    Real result(precision);
    mpfi_set_q(result.get(), q.get_mpq_t());
    return result;
}

bool exact_interval(Real& result, mpfr_srcptr lo, mpfr_srcptr hi) {
    Real candidate(result.precision());
    if (mpfi_interv_fr(candidate.get(), lo, hi) != 0) return false;
    result = candidate;
    return true;
}

Real operator+(const Real& a, const Real& b) {
    Real r(joint(a, b));
    mpfi_add(r.get(), a.get(), b.get());
    return r;
}
Real operator-(const Real& a, const Real& b) {
    Real r(joint(a, b));
    mpfi_sub(r.get(), a.get(), b.get());
    return r;
}
Real operator*(const Real& a, const Real& b) {
    Real r(joint(a, b));
    mpfi_mul(r.get(), a.get(), b.get());
    return r;
}
Real operator/(const Real& a, const Real& b) {
    if (!excludes_zero(b)) throw std::domain_error("division by an interval that may contain 0");
    Real r(joint(a, b));
    mpfi_div(r.get(), a.get(), b.get());
    return r;
}
Real operator-(const Real& a) {
    Real r(a.precision());
    mpfi_neg(r.get(), a.get());
    return r;
}
Real operator*(long n, const Real& a) { return integer(n, a.precision()) * a; }

Real exp(const Real& x) {
    Real r(x.precision());
    mpfi_exp(r.get(), x.get());
    return r;
}
Real log(const Real& x) {
    if (!positive(x)) throw std::domain_error("log of an interval that may be <= 0");
    Real r(x.precision());
    mpfi_log(r.get(), x.get());
    return r;
}
Real expm1(const Real& x) {
    Real r(x.precision());
    mpfi_expm1(r.get(), x.get());
    return r;
}
Real log1p(const Real& x) {
    if (!positive(x + integer(1, x.precision()))) throw std::domain_error("log1p of an interval that may be <= -1");
    Real r(x.precision());
    mpfi_log1p(r.get(), x.get());
    return r;
}
Real abs(const Real& x) {
    Real r(x.precision());
    mpfi_abs(r.get(), x.get());
    return r;
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
        mpfr_t down, up;
        mpfr_inits2(precision, down, up, static_cast<mpfr_ptr>(nullptr));
        function(down, point, MPFR_RNDD);
        function(up, point, MPFR_RNDU);
        mpfi_interv_fr(result.get(), down, up);
        mpfr_clears(down, up, static_cast<mpfr_ptr>(nullptr));
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
    Real r(joint(a, b));
    mpfi_union(r.get(), a.get(), b.get());
    return r;
}
Real lower_point(const Real& x) {
    Real r(x.precision());
    mpfi_interv_fr(r.get(), x.lo(), x.lo());
    return r;
}
Real upper_point(const Real& x) {
    Real r(x.precision());
    mpfi_interv_fr(r.get(), x.hi(), x.hi());
    return r;
}
Real midpoint(const Real& x) {
    mpfr_t center;
    mpfr_init2(center, x.precision());
    mpfi_mid(center, x.get());
    // mpfi_mid rounds to nearest; clamp so that the point lies in x whatever happened.
    if (mpfr_cmp(center, x.lo()) < 0) mpfr_set(center, x.lo(), MPFR_RNDN);
    if (mpfr_cmp(center, x.hi()) > 0) mpfr_set(center, x.hi(), MPFR_RNDN);
    Real r(x.precision());
    mpfi_interv_fr(r.get(), center, center);
    mpfr_clear(center);
    return r;
}
bool intersect(Real& result, const Real& a, const Real& b) {
    if (mpfr_cmp(a.hi(), b.lo()) < 0 || mpfr_cmp(b.hi(), a.lo()) < 0) return false;
    Real r(joint(a, b));
    mpfi_interv_fr(r.get(), mpfr_cmp(a.lo(), b.lo()) > 0 ? a.lo() : b.lo(), mpfr_cmp(a.hi(), b.hi()) < 0 ? a.hi() : b.hi());
    result = r;
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
