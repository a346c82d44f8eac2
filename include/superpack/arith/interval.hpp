// The interval concept shared by every formula in superpack, and its two backends:
//   DInterval  binary64 endpoints, directed rounding in round-to-nearest (fast path, ~15 digits);
//   Ball       Arb balls at any precision (selected with --digits).
// Every formula is a template over the interval type I, so both paths share one source.
//
// Predicates follow the Arb/IBEX convention: certainly_* holds for every point of the
// enclosure (false when unsure); possibly_* / contains_* hold for at least one point.
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "superpack/arith/ball.hpp"
#include "superpack/arith/exact.hpp"
#include "superpack/arith/interval_double.hpp"

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
    long precision;
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

// ---- plain doubles, for guesses only --------------------------------------------------
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
inline double unbounded_above(double) { return std::numeric_limits<double>::infinity(); }

// x^y for a positive x, as one ball evaluation of exp(y log x) (Arb): tight when x is narrow,
// and one library call instead of four, which is most of a density's cost.
DInterval power_of_positive(const DInterval& x, const DInterval& y);
Ball power_of_positive(const Ball& x, const Ball& y);

// Unbounded enclosures. [lower, +inf]: a DInterval holds it exactly; a Ball has no one-sided
// infinite form and becomes the whole line [0 +- inf]. The whole line is (-inf, inf) in both.
inline DInterval unbounded_above(const DInterval& lower) {
    return DInterval(lower.lower(), std::numeric_limits<double>::infinity());
}
Ball unbounded_above(const Ball& lower);
inline DInterval whole_line(const DInterval&) { return DInterval::whole(); }
inline Ball whole_line(const Ball& like) { return unbounded_above(like); }
// Both ends finite. An unbounded enclosure bounds no slope or step (roots.hpp).
inline bool bounded(const DInterval& x) { return std::isfinite(x.lower()) && std::isfinite(x.upper()); }
bool bounded(const Ball& x);
// The same interval, bit for bit (a replayed partition must reproduce its pieces).
inline bool same_interval(const DInterval& a, const DInterval& b) { return a.lower() == b.lower() && a.upper() == b.upper(); }
bool same_interval(const Ball& a, const Ball& b);

// Positive and narrower than 2^-16 of its size: where one ball evaluation is as tight as the
// endpoint hull (the fast paths of the powers below and in jet.hpp).
template <class I>
bool narrow_positive(const I& x) {
    return certainly_positive(x) && width_upper(x) <= std::ldexp(mid_double(x), -16);
}

template <class I>
bool is_zero_point(const I& x) {
    return contains_zero(x) && width_upper(x) == 0.0;
}

// x^y for a base x >= 0 and an exponent y that is exactly one of the points 1, ..., 8, 1/2 or
// 1/4 (2p, 2p - 1 and 1/(2p) at p = 1/2, 1, 3/2, 2, ...): by products and squares of x, or
// by the outward rounded sqrt. x -> x^y is increasing on x >= 0, so the operations enclose
// x^y on the whole base, and they cost far less than exp and log, which were 40% of the
// critical-lattice search at p = 2. Nothing for any other exponent, and where a Ball
// product (midpoint-radius) reaches below 0, so that the caller takes the general path.
template <class I>
std::optional<I> power_by_products(const I& x, const I& y) {
    if (width_upper(y) != 0.0) return std::nullopt;
    const auto field = field_of(x);
    const double guess = mid_double(y);
    if (guess == 0.5 || guess == 0.25) {
        const I root = field.integer(1) / field.integer(guess == 0.5 ? 2 : 4);
        if (!contains(y, root)) return std::nullopt;
        const I result = guess == 0.5 ? sqrt(x) : sqrt(sqrt(x));
        if (!certainly_nonnegative(result)) return std::nullopt;
        return result;
    }
    if (!(guess >= 1 && guess <= 8 && guess == std::floor(guess))) return std::nullopt;
    const long n = static_cast<long>(guess);
    if (!contains(y, field.integer(n))) return std::nullopt;
    I power = x, squares = x;  // x^n = product of x^(2^k) over the bits k of n
    bool first = true;
    for (long bits = n; bits > 0; bits >>= 1) {
        if (bits & 1) {
            power = first ? squares : power * squares;
            first = false;
        }
        if (bits > 1) squares = square(squares);
    }
    if (!certainly_nonnegative(power)) return std::nullopt;
    return power;
}

// x^y for a base x >= 0 and any exponent y: encloses x^y for every point of x and of y, with
// 0^y = 0 for y > 0 and 0^0 = 1 (the limit needed by derivatives at p = 1/2).
// Contract (enforced): a base that may be negative is refused, and so is the base 0 (a
// point) with an exponent that may be negative, where 0^y is no real number. A base [0, b]
// reaching 0 with an exponent that may be < 0 has an unbounded range, since x^y -> +inf as
// x -> 0 for y < 0, and gets the true, unbounded enclosure (see unbounded_above):
//   y > 0: [0, b^y];  y = 0 exactly: 1;  0 <= y (y not a point): [0, max(1, b^y)];
//   y < 0: [b^y, +inf];  y <= 0 (not a point): [min(1, b^y), +inf];  y straddling 0: [0, +inf].
// On a base away from 0, x -> x^y is monotone for each y, so the hull of exp(y log x) at the
// two ends of x holds every value.
template <class I>
I pow_nonneg(const I& x, const I& y) {
    const auto field = field_of(x);
    if (!certainly_nonnegative(x)) throw std::domain_error("pow_nonneg: base may be negative");
    if (const std::optional<I> by_products = power_by_products(x, y)) return *by_products;
    if (narrow_positive(x)) return power_of_positive(x, y);
    if (is_zero_point(y)) return field.integer(1);
    const I b = upper_point(x);
    if (certainly_positive(x)) return hull(exp(y * log(lower_point(x))), exp(y * log(b)));
    const I zero = field.integer(0), one = field.integer(1);
    const bool nonnegative = certainly_nonnegative(y), nonpositive = certainly_nonnegative(-y);
    if (!certainly_positive(b)) {  // x is the point 0
        if (certainly_positive(y)) return zero;
        if (nonnegative) return hull(zero, one);
        throw std::domain_error("pow_nonneg: 0^y with y possibly < 0");
    }
    const I high = exp(y * log(b));  // b^y for every y
    if (certainly_positive(y)) return hull(zero, high);
    if (nonnegative) return hull(hull(zero, one), high);
    if (certainly_negative(y)) return unbounded_above(high);
    if (nonpositive) return unbounded_above(hull(one, high));
    return unbounded_above(zero);
}

// |x|^y for any real x (the contract of pow_nonneg on |x|).
template <class I>
I pow_abs(const I& x, const I& y) {
    return pow_nonneg(abs(x), y);
}

// sign(x) |x|^y, the derivative kernel of |x|^(y+1). Where x reaches 0 the values lie in
// [-M, M], M = max |x|^y, if y >= 0 (for y = 0 exactly that is sign(x) in [-1, 1]); if y may
// be < 0, |x|^y is unbounded near 0 and the result is the whole line.
template <class I>
I pow_signed(const I& x, const I& y) {
    if (certainly_positive(x)) return pow_nonneg(x, y);
    if (certainly_negative(x)) return -pow_nonneg(-x, y);
    if (!certainly_nonnegative(y)) return whole_line(x);
    const I magnitude = upper_point(pow_abs(x, y));
    return hull(-magnitude, magnitude);
}

}  // namespace superpack
