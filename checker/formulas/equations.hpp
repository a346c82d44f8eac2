// The formulas the checker needs, written again from the papers (Jiao, Stillinger, Torquato
// 2009; Dostert, Vallentin 2020 for D14) in the checker's own arithmetic: the contact equations with their derivatives
// (derived by hand, no automatic differentiation), the lattice bases, the 3x3 determinant
// and the superball volume. Nothing here is shared with the producer.
#pragma once
#include <array>

#include "checker/core/real.hpp"

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

// D14 (Dostert and Vallentin, Adv. Geom. 20 (2020), Theorem 4.2, their exponent 2p), unknowns
// (x, y, z): F0 = |x|^(2p) + |y|^(2p) + |z|^(2p) - 1, F1 = |x-y|^(2p) + |z-x|^(2p) + |y+z|^(2p) - 1,
// F2 = 3|y+z-x|^(2p) - 1.
struct D14Equations {
    Real p;
    std::array<Real, 3> value(const std::array<Real, 3>& v) const;
    std::array<std::array<Real, 3>, 3> jacobian(const std::array<Real, 3>& v) const;
};

// Bases (rows) of the families: C0 Eq. 1, C1 Eq. 8, O0 Eq. 5, O1 Eq. 11; D14 2(-x, y, z),
// 2(z, -x, y), 2(y, z, -x).
Matrix3 c0_basis(const Real& s, const Real& t);
Matrix3 c1_basis(const Real& s, const Real& t);
Real o0_height(const Real& p);  // c = (1 - 2^(1-2p))^(1/(2p))
Matrix3 o0_basis(const Real& c);
Matrix3 o1_basis(const Real& q, const Real& s, const Real& l);
Matrix3 d14_basis(const Real& x, const Real& y, const Real& z);

Real determinant(const Matrix3& m);
// ||v||_(2p) = 2 (sum |v_i / 2|^(2p))^(1/(2p)): the halves of the candidates' coordinates are
// at most about 1, so their powers neither overflow MPFR's exponent range (2^(2p) would for
// p > 5e8) nor, on a wide p interval, grow with 2p.
Real lattice_norm(const std::array<Real, 3>& v, const Real& two_p);
// V_sb(p) = (2 Gamma(1 + 1/(2p)))^3 / Gamma(1 + 3/(2p)).
Real superball_volume(const Real& p);

}  // namespace superpack_checker
