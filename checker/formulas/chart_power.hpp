// The powers of the critical-lattice chart (chart_forms.hpp), in the checker's arithmetic: |x|^y
// and sign(x) |x|^y for the coordinates and the configuration vectors (y = 2p and 2p - 1, both
// > 0 since p > 1/2, at bases that may be 0), and x^y on bases certainly > 0 (y = 1/(2p) and
// 1/(2p) - 1 at the sums in [1, 3] of a cube face). Each is endpoint-wise: x -> x^y is monotone
// on x >= 0 for every y, and at one base y -> x^y is monotone, so the values at the two ends of
// |x|, each enclosed for every y of the exponent interval, bound the whole range. That is the
// tightest enclosure there is, and so it lies inside the producer's (NOTES.md 12.8).
#pragma once
#include "checker/core/real.hpp"

namespace superpack_checker {

// A point exponent a/b with 1 <= b <= max_root and |a| <= max_power (denominator 0: none), which
// the power takes as the b-th root of e^|a|, each rounded outward by MPFR (inverted for a < 0),
// instead of exp(y log e): exp and log are the dearest operations of the replay. Every exponent
// of the chart is such a point at a p = m/n with small m and n (2p, 2p - 1, 1/(2p), 1/(2p) - 1:
// at p = 3/5 they are 6/5, 1/5, 5/6 and -1/6).
struct ExactExponent {
    long numerator = 0;
    unsigned long denominator = 0;
};
constexpr unsigned long max_root = 64;
constexpr long max_power = 256;

// An exponent y with y - 1 beside it (the exponent of the derivative kernel), each enclosed and,
// where it is such a point, exact.
struct Exponent {
    Real y, y_minus_one;
    ExactExponent exact, exact_minus_one;
};
Exponent exponent(const mpq_class& y, mpfr_prec_t precision);

// |x|^y for y >= 0 (0^y needs y > 0).
Real chart_pow_abs(const Real& x, const Exponent& y);
// x^y for x certainly > 0 and any y.
Real chart_pow_positive(const Real& x, const Exponent& y);
// A power and its derivative kernel together, from one power per end (the kernel at an end
// e > 0 is e^y / e, which at a point loses nothing): |x|^y with sign(x) |x|^(y-1), and x^y
// with x^(y-1) for x certainly > 0.
struct PowerPair {
    Real value, kernel;
};
PowerPair chart_pow_abs_pair(const Real& x, const Exponent& y);
PowerPair chart_pow_positive_pair(const Real& x, const Exponent& y);

}  // namespace superpack_checker
