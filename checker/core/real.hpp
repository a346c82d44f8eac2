// The checker's own arithmetic: closed intervals [lo, hi] with MPFR endpoints (in MPFI's
// layout, so that MPFI may read them), at a precision fixed per certificate. The operations are
// written here with MPFR's directed rounding; tests/test_checker_real.cpp compares them with
// MPFI's. This file and its siblings include nothing from superpack's include/ (no
// interval.hpp, families.hpp, roots.hpp): the checker shares only JSON parsing with the
// producer, so a bug in the producer's arithmetic cannot hide itself.
#pragma once
#include <gmpxx.h>
#include <mpfi.h>

#include <cstddef>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace superpack_checker {

class Real {
public:
    explicit Real(mpfr_prec_t precision);  // the point 0
    Real(const Real& other);
    Real& operator=(const Real& other);
    ~Real() = default;

    mpfi_srcptr get() const { return value_; }
    mpfr_prec_t precision() const { return precision_; }
    mpfr_srcptr lo() const { return &value_->left; }
    mpfr_srcptr hi() const { return &value_->right; }
    // The ends, to be written by MPFR functions that round them (down for lo, up for hi). The
    // storage is the Real's own: never mpfr_set_prec, mpfr_swap or mpfr_clear them, nor write
    // them with MPFI (whose functions may swap an end with a temporary of their own).
    mpfr_ptr lower_end() { return &value_->left; }
    mpfr_ptr upper_end() { return &value_->right; }

private:
    // Ends of up to 256 bits (every certificate up to about 57 digits) live inside the Real, so
    // that the checker's arithmetic allocates nothing: MPFR's allocation was 43% of a replay.
    static constexpr std::size_t inline_limbs = 4;
    void attach(mpfr_prec_t precision);
    void copy_ends(const Real& other);  // of the same precision

    mpfi_t value_;
    mpfr_prec_t precision_;
    mp_limb_t inline_[2 * inline_limbs];
    std::unique_ptr<mp_limb_t[]> heap_;
};

Real integer(long n, mpfr_prec_t precision);
Real rational(const mpq_class& q, mpfr_prec_t precision);  // outward rounded
// Exactly [lo, hi]; false (and nothing set) when an end needs more than `precision` bits.
bool exact_interval(Real& result, mpfr_srcptr lo, mpfr_srcptr hi);
// [lo, hi] rounded outward to `precision` (ends in either order; a NaN end makes both NaN).
Real outward(mpfr_srcptr lo, mpfr_srcptr hi, mpfr_prec_t precision);
Real pi(mpfr_prec_t precision);
Real doubles(double lo, double hi, mpfr_prec_t precision);  // [lo, hi], exact from 53 bits on (as outward)

Real operator+(const Real& a, const Real& b);
Real operator-(const Real& a, const Real& b);
Real operator*(const Real& a, const Real& b);
Real operator/(const Real& a, const Real& b);  // b must exclude 0 (else the result is unbounded)
Real operator-(const Real& a);
Real operator*(long n, const Real& a);

Real exp(const Real& x);
Real log(const Real& x);  // x > 0
Real log1p(const Real& x);  // log(1 + x) for x > -1, accurate near 0 (MPFR's mpfr_log1p)
Real expm1(const Real& x);  // exp(x) - 1, accurate near 0 (MPFR's mpfr_expm1)
Real abs(const Real& x);
Real sqrt(const Real& x);    // x >= 0
Real square(const Real& x);  // x^2, at or above 0 where x spans 0
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
