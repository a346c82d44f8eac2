// The formulas the checker needs, written again from the paper (Jiao, Stillinger, Torquato
// 2009) in the checker's own arithmetic: the contact equations with their derivatives
// (derived by hand, no automatic differentiation), the lattice bases, the 3x3 determinant
// and the superball volume. Nothing here is shared with the producer.
#pragma once
#include <array>

#include "checker/real.hpp"

namespace superpack_checker {

using Matrix3 = std::array<std::array<Real, 3>, 3>;

// C0 (Eq. 2): f(s) = |s + t|^(2p) + |s|^(2p) + 2^(-2p) - 1,  t = 2^(-1/(2p));
// C1 (Eq. 9): f(s) = |s + t|^(2p) + 2|s|^(2p) - 1.
struct CubicEquation {
    bool c1;  // false: C0
    Real p;
    Real value(const Real& s) const;
    Real derivative(const Real& s) const;
    Real shift() const;  // t
};

// O1 (Eq. 12), unknowns (q, s), l = 3^(-1/(2p)):
//   F0 = 2|q|^(2p) + |s|^(2p) - 1,  F1 = |q + l|^(2p) + |s - l|^(2p) + |l - q|^(2p) - 1.
struct OctahedralEquations {
    Real p;
    std::array<Real, 2> value(const std::array<Real, 2>& x) const;
    std::array<std::array<Real, 2>, 2> jacobian(const std::array<Real, 2>& x) const;
    Real l() const;
};

// Bases (rows) of the families: C0 Eq. 1, C1 Eq. 8, O0 Eq. 5, O1 Eq. 11.
Matrix3 c0_basis(const Real& s, const Real& t);
Matrix3 c1_basis(const Real& s, const Real& t);
Real o0_height(const Real& p);  // c = (1 - 2^(1-2p))^(1/(2p))
Matrix3 o0_basis(const Real& c);
Matrix3 o1_basis(const Real& q, const Real& s, const Real& l);

Real determinant(const Matrix3& m);
// V_sb(p) = (2 Gamma(1 + 1/(2p)))^3 / Gamma(1 + 3/(2p)).
Real superball_volume(const Real& p);

}  // namespace superpack_checker
