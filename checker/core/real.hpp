// The checker's own arithmetic: closed intervals [lo, hi] with MPFR endpoints (MPFI), at a
// precision fixed per certificate. This file and its siblings include nothing from
// superpack's include/ (no interval.hpp, families.hpp, roots.hpp): the checker shares only
// JSON parsing with the producer, so a bug in the producer's arithmetic cannot hide itself.
#pragma once
#include <gmpxx.h>
#include <mpfi.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace superpack_checker {

class Real {
public:
    explicit Real(mpfr_prec_t precision);  // the point 0
    Real(const Real& other);
    Real(Real&& other) noexcept;
    Real& operator=(const Real& other);
    Real& operator=(Real&& other) noexcept;
    ~Real();

    mpfi_ptr get() { return value_; }
    mpfi_srcptr get() const { return value_; }
    mpfr_prec_t precision() const { return precision_; }
    mpfr_srcptr lo() const { return &value_->left; }
    mpfr_srcptr hi() const { return &value_->right; }

private:
    mpfi_t value_;
    mpfr_prec_t precision_;
};

Real integer(long n, mpfr_prec_t precision);
Real rational(const mpq_class& q, mpfr_prec_t precision);  // outward rounded
// Exactly [lo, hi]; false (and nothing set) when an end needs more than `precision` bits.
bool exact_interval(Real& result, mpfr_srcptr lo, mpfr_srcptr hi);

Real operator+(const Real& a, const Real& b);
Real operator-(const Real& a, const Real& b);
Real operator*(const Real& a, const Real& b);
Real operator/(const Real& a, const Real& b);  // b must exclude 0 (else the result is unbounded)
Real operator-(const Real& a);
Real operator*(long n, const Real& a);

Real exp(const Real& x);
Real log(const Real& x);  // x > 0
Real log1p(const Real& x);  // log(1 + x) for x > -1, accurate near 0 (MPFI's mpfi_log1p)
Real expm1(const Real& x);  // exp(x) - 1, accurate near 0 (MPFI's mpfi_expm1)
Real abs(const Real& x);
// |x|^y for a nonnegative exponent y (the point 0 gives 1; an exponent interval reaching 0
// needs |x| > 0): endpoint-wise, as x -> |x|^y is monotone on each side of 0.
Real pow_abs(const Real& x, const Real& y);
// sign(x) |x|^y, the derivative kernel of |x|^(y+1); [-M, M] when x may change sign.
Real pow_signed(const Real& x, const Real& y);
// Gamma on x > 0 from MPFR's correctly rounded mpfr_gamma and mpfr_digamma at the endpoints:
// monotone where digamma has one sign, else a mean-value lower bound around the minimum.
Real gamma(const Real& x);

Real hull(const Real& a, const Real& b);
Real lower_point(const Real& x);
Real upper_point(const Real& x);
Real midpoint(const Real& x);  // a point of x
bool intersect(Real& result, const Real& a, const Real& b);  // false when a and b are disjoint

// Certainly-predicates (true only when proved for every point).
bool positive(const Real& x);
bool negative(const Real& x);
bool excludes_zero(const Real& x);
bool less(const Real& a, const Real& b);
bool subset(const Real& inner, const Real& outer);           // inner within outer
bool interior_subset(const Real& inner, const Real& outer);  // inner within the interior of outer
// The width of an interval, for stopping rules and tolerances only: 53 bits rounded up, with MPFR's
// exponent range. A double does not do: below 2^-1074 every width rounds up to the same subnormal, so a
// rule "stop when an iterate no longer shrinks" stopped at about 320 digits, whatever the
// precision, and left the checker's boxes wider than those of a 700-digit certificate.
class Width {
public:
    Width(double x = 0);  // exact
    Width(const Width& other);
    Width& operator=(const Width& other);
    ~Width();
    mpfr_srcptr get() const { return value_; }
    mpfr_ptr get() { return value_; }

private:
    mpfr_t value_;
};
Width width(const Real& x);
Width operator+(const Width& a, const Width& b);  // rounded up
Width operator*(double factor, const Width& w);   // rounded up
Width scaled(const Width& w, long exponent);      // w 2^exponent
Width magnitude(const Real& x);                   // max(1, |lo|, |hi|) rounded up: a relative tolerance's scale
bool operator<(const Width& a, const Width& b);
bool operator<=(const Width& a, const Width& b);
bool operator>(const Width& a, const Width& b);
bool operator>=(const Width& a, const Width& b);
bool operator==(const Width& a, const Width& b);
std::ostream& operator<<(std::ostream& out, const Width& w);  // 6 digits, for messages
double middle(const Real& x);  // for preconditioners only

std::string text(const Real& x);  // "[lo, hi]" to 20 digits, for messages

}  // namespace superpack_checker
