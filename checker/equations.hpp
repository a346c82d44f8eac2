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
    Real shifted_power(const Real& s, bool lowered) const;  // (s + t)^(2p), or ^(2p - 1) if lowered; s > -t
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
// ||v||_(2p) = 2 (sum |v_i / 2|^(2p))^(1/(2p)): the halves of the candidates' coordinates are
// at most about 1, so their powers neither overflow MPFR's exponent range (2^(2p) would for
// p > 5e8) nor, on a wide p interval, grow with 2p.
Real lattice_norm(const std::array<Real, 3>& v, const Real& two_p);
// V_sb(p) = (2 Gamma(1 + 1/(2p)))^3 / Gamma(1 + 3/(2p)).
Real superball_volume(const Real& p);

}  // namespace superpack_checker
