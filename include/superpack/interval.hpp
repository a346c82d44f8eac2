// The interval concept shared by every formula in superpack, and its two backends:
//   DInterval  binary64 endpoints, directed rounding in round-to-nearest (fast path, ~15 digits);
//   Ball       Arb balls at any precision (selected with --digits).
// Every formula is a template over the interval type I, so both paths share one source.
//
// Predicates follow the Arb/IBEX convention: certainly_* holds for every point of the
// enclosure (false when unsure); possibly_* / contains_* hold for at least one point.
#pragma once
#include <mpfr.h>

#include <cmath>
#include <stdexcept>

#include <string>

#include "superpack/ball.hpp"
#include "superpack/exact.hpp"
#include "superpack/interval_double.hpp"

namespace superpack {

// A field names a backend and its working precision; formulas take it as their last argument
// and use it to make constants.
struct DoubleField {
    using Interval = DInterval;
    long bits() const { return 53; }
    const char* backend() const { return "binary64-interval (Boost.Interval, directed rounding from exact residuals, series exp/log/Gamma with proved bounds)"; }
    DInterval rational(const Rational& q) const;
    DInterval integer(long n) const { return DInterval(static_cast<double>(n)); }
    DInterval pi() const;
};

struct BallField {
    using Interval = Ball;
    slong precision;
    long bits() const { return precision; }
    const char* backend() const { return "arb-ball (Arb 2.23, MPFR-free midpoint-radius)"; }
    Ball rational(const Rational& q) const;
    Ball integer(long n) const;
    Ball pi() const;
};

inline DoubleField field_of(const DInterval&) { return {}; }
inline BallField field_of(const Ball& x) { return {x.precision()}; }

// Bits for a requested number of significant decimal digits, with guard bits for the
// cancellations inside the contact equations.
long bits_for_digits(long digits);

// ---- elementary functions (rigorous, outward rounded) -------------------------------
DInterval exp(const DInterval& x);
DInterval log(const DInterval& x);  // requires x > 0
DInterval log1p(const DInterval& x);  // log(1 + x) with relative accuracy near 0; requires x > -1
DInterval expm1(const DInterval& x);  // exp(x) - 1 with relative accuracy near 0
DInterval sqrt(const DInterval& x);
DInterval square(const DInterval& x);
DInterval abs(const DInterval& x);
DInterval gamma(const DInterval& x);    // requires x > 0
DInterval digamma(const DInterval& x);  // requires x > 0
Ball exp(const Ball& x);
Ball log(const Ball& x);
Ball log1p(const Ball& x);
Ball expm1(const Ball& x);
Ball sqrt(const Ball& x);
Ball square(const Ball& x);
Ball abs(const Ball& x);
Ball gamma(const Ball& x);
Ball digamma(const Ball& x);

// ---- endpoints, hulls, predicates ---------------------------------------------------
DInterval lower_point(const DInterval& x);
DInterval upper_point(const DInterval& x);
DInterval midpoint(const DInterval& x);  // a point inside x
DInterval hull(const DInterval& a, const DInterval& b);
bool intersect(DInterval& result, const DInterval& a, const DInterval& b);  // false if empty
Ball lower_point(const Ball& x);
Ball upper_point(const Ball& x);
Ball midpoint(const Ball& x);
Ball hull(const Ball& a, const Ball& b);
bool intersect(Ball& result, const Ball& a, const Ball& b);

bool certainly_positive(const DInterval& x);
bool certainly_negative(const DInterval& x);
bool certainly_nonnegative(const DInterval& x);
bool certainly_less(const DInterval& a, const DInterval& b);
bool contains_zero(const DInterval& x);
bool contains(const DInterval& outer, const DInterval& inner);
bool interior_contains(const DInterval& outer, const DInterval& inner);
bool certainly_positive(const Ball& x);
bool certainly_negative(const Ball& x);
bool certainly_nonnegative(const Ball& x);
bool certainly_less(const Ball& a, const Ball& b);
bool contains_zero(const Ball& x);
bool contains(const Ball& outer, const Ball& inner);
bool interior_contains(const Ball& outer, const Ball& inner);

// Doubles for guesses and stopping rules only (never for a verdict).
double mid_double(const DInterval& x);
double mid_double(const Ball& x);
double width_upper(const DInterval& x);  // an upper bound on hi - lo
double width_upper(const Ball& x);
// An interval from two doubles, exactly (both backends hold every double exactly).
DInterval from_doubles(const DInterval& like, double lo, double hi);
Ball from_doubles(const Ball& like, double lo, double hi);

// Endpoints as MPFR numbers, rounded outward to the precision of lo and hi.
void get_bounds(mpfr_t lo, mpfr_t hi, const DInterval& x);
void get_bounds(mpfr_t lo, mpfr_t hi, const Ball& x);

// ---- plain doubles, for guesses only (STYLE P6) --------------------------------------
// The generic formulas can be instantiated with double to find starting boxes quickly.
// Nothing computed with these is reported or used as a verdict: every guess is re-verified
// in interval arithmetic. They live here so that templates defined below see them.
struct GuessField {
    double integer(long n) const { return static_cast<double>(n); }
};
inline GuessField field_of(double) { return {}; }
inline double exp(double x) { return std::exp(x); }
inline double log(double x) { return std::log(x); }
inline double log1p(double x) { return std::log1p(x); }
inline double expm1(double x) { return std::expm1(x); }
inline double pow_nonneg(double x, double y) { return std::pow(x, y); }
inline double pow_abs(double x, double y) { return std::pow(std::fabs(x), y); }
inline double pow_signed(double x, double y) { return std::copysign(std::pow(std::fabs(x), y), x); }

// x^y for x >= 0 as exp(y log x), evaluated at the endpoints of x: for a fixed y the map
// x -> x^y is monotone, so the hull of the two endpoint enclosures holds every value.
// At x = 0 the lower value is 0 when y > 0 and 1 when y = 0 exactly (the limit used by
// derivatives at p = 1/2); a possibly non-positive y with x touching 0 is a contract error.
// x^y for a positive x, as one ball evaluation of exp(y log x) (Arb): tight when x is narrow,
// and one library call instead of four, which is most of a density's cost.
DInterval power_of_positive(const DInterval& x, const DInterval& y);
Ball power_of_positive(const Ball& x, const Ball& y);

// Positive and narrower than 2^-16 of its size: where one ball evaluation is as tight as the
// endpoint hull (the fast paths of the powers below and in jet.hpp).
template <class I>
bool narrow_positive(const I& x) {
    return certainly_positive(x) && width_upper(x) <= std::ldexp(mid_double(x), -16);
}

template <class I>
I pow_nonneg(const I& x, const I& y) {
    const auto field = field_of(x);
    if (!certainly_nonnegative(x)) throw std::domain_error("pow_nonneg: base may be negative");
    if (narrow_positive(x)) return power_of_positive(x, y);
    const I a = lower_point(x), b = upper_point(x);
    auto endpoint = [&](const I& base) -> I {
        if (certainly_positive(base)) return exp(y * log(base));
        if (certainly_positive(y)) return field.integer(0);
        if (!contains_zero(y) || width_upper(y) != 0.0)
            throw std::domain_error("pow_nonneg: 0^y with y possibly <= 0");
        return field.integer(1);
    };
    if (!certainly_positive(b)) return endpoint(b);  // x is the point 0
    const I high = endpoint(b);
    if (certainly_positive(a)) return hull(endpoint(a), high);
    // a = 0: x^y ranges down to 0 (y > 0) or is 1 at y = 0; both lie in hull(0 or 1, b^y).
    const I low = certainly_positive(y) ? field.integer(0) : hull(field.integer(0), field.integer(1));
    return hull(low, high);
}

// |x|^y for any real x.
template <class I>
I pow_abs(const I& x, const I& y) {
    return pow_nonneg(abs(x), y);
}

// sign(x) |x|^y, the derivative kernel of |x|^(y+1); [-M, M] when x straddles 0.
template <class I>
I pow_signed(const I& x, const I& y) {
    if (certainly_positive(x)) return pow_nonneg(x, y);
    if (certainly_negative(x)) return -pow_nonneg(-x, y);
    const I magnitude = upper_point(pow_abs(x, y));
    return hull(-magnitude, magnitude);
}

}  // namespace superpack
