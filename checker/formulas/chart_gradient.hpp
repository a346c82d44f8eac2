// A value with its six partial derivatives in the chart coordinates x = (s, t, a2, c2, a3, c3),
// enclosed over a box: the checker's form of the producer's Jets (include/superpack/arith/
// jet.hpp), which run one pass per coordinate. The derivative rules are the Jets' term for term
// ((ab)' = a'b + ab', (a/b)' = (a' - (a/b) b') / b, |x|^y' = (y sign(x) |x|^(y-1)) x', ...), so
// each partial derivative is the same expression tree as the producer's pass for that
// coordinate, and its enclosure lies inside the producer's. A partial that is exactly 0 (a
// coordinate the value does not depend on: b2 has only a2 and c2) is not computed: the Jet's
// terms with a zero factor are the point 0, and adding 0 changes no enclosure.
#pragma once
#include <array>
#include <optional>

#include "checker/formulas/chart_power.hpp"

namespace superpack_checker {

constexpr int chart_dimension = 6;

struct Gradient {
    Real value;
    // slope[k] = d value / dx_k over the box; empty where it is exactly 0 (the value does not
    // depend on x_k), which also spares the zero's allocation.
    std::array<std::optional<Real>, chart_dimension> slope;
};
// slope[k] as an interval (the point 0 where it is empty).
Real slope_at(const Gradient& g, int k);

Gradient constant(const Real& x);
Gradient variable(const Real& x, int k);  // the coordinate x_k over the interval x

Gradient operator+(const Gradient& a, const Gradient& b);
Gradient operator-(const Gradient& a, const Gradient& b);
Gradient operator-(const Gradient& a);
Gradient operator*(const Gradient& a, const Gradient& b);
Gradient operator/(const Gradient& a, const Gradient& b);
Gradient operator*(const Real& c, const Gradient& a);  // a constant factor
Gradient operator*(const Gradient& a, const Real& c);

// |x|^y (y > 1 here): (y sign(x) |x|^(y-1)) x'.
Gradient chart_pow_abs(const Gradient& x, const Exponent& y);
// x^y for x certainly > 0: (y x^(y-1)) x'.
Gradient chart_pow_positive(const Gradient& x, const Exponent& y);

}  // namespace superpack_checker
