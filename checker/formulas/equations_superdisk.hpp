// The superdisk formulas the checker needs (claim kind "superdisk-optimum"), written again in
// the checker's arithmetic from the definitions, with every derivative derived by hand:
//   K = {|x|^q + |y|^q <= 1}, q = 2p;  u(t) = (x, t x), x(t) = (1 + |t|^q)^(-1/q);
//   contact system for v = (a, b): F0 = |a|^q + |b|^q - 1, F1 = |a - x|^q + |b - t x|^q - 1;
//   D(t) = det(u, v) = x b - t x a, and D'(t) by implicit differentiation of F = 0;
//   area(K) = 4 Gamma(1 + 1/(2p))^2 / Gamma(1 + 1/p).
// Nothing here is shared with the producer (its superdisk header and driver).
#pragma once
#include <array>

#include "checker/core/real.hpp"

namespace superpack_checker {

struct SuperdiskEquations {
    Real p;  // p > 1/2, so q - 1 > 0 and every |.|^(q-1) below is continuous

    Real exponent() const;                 // q = 2p
    Real boundary_x(const Real& t) const;  // x(t)
    // x'(t) = -(1 + |t|^q)^(-1/q - 1) sign(t) |t|^(q-1) = -x^(q+1) sign(t) |t|^(q-1).
    Real boundary_x_derivative(const Real& t) const;
    std::array<Real, 2> contact(const Real& a, const Real& b, const Real& t) const;
    // d(F0, F1) / d(a, b): d|z|^q/dz = q sign(z) |z|^(q-1).
    std::array<std::array<Real, 2>, 2> jacobian(const Real& a, const Real& b, const Real& t) const;
    Real determinant(const Real& a, const Real& b, const Real& t) const;  // D = x (b - t a)
    // D' = dD/dt + D_a a' + D_b b', with J (a', b') = -(0, dF1/dt) solved by Cramer's rule.
    // Its Jacobian determinant must exclude 0 (else the result is unbounded).
    Real derivative(const Real& a, const Real& b, const Real& t) const;
    // At t = 0 (x = 1) the system gives |a| = |a - 1|: v = (1/2, y1), y1 = (1 - 2^-q)^(1/q).
    Real axis_height() const;
    // For t in [0, 1] and every solution (a, b) with det(u, v) > 0: b >= y1, and a <= 0 or
    // 0 <= a <= min(x/2, x - (1 - 2^-q - (y1 - t x)^q)^(1/q)); so D >= x y1 - t x max(0, min(...))
    // (NOTES.md 7.4, "A priori bound"). Lower end of that over the interval t.
    Real a_priori_lower_bound(const Real& t) const;
};

// area(K) = 4 Gamma(1 + 1/(2p))^2 / Gamma(1 + 1/p).
Real superdisk_area(const Real& p);

}  // namespace superpack_checker
