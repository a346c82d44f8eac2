// The checker's formulas for the crossover and slope claims, written again by hand in its own
// arithmetic (no automatic differentiation, nothing from the producer): the p-derivatives of
// the pieces of phi = V_sb(p) / |det B| for C0, C1 and O0, the implicit derivative of the
// contact root s(p), the closed-form determinants (proved equal to the determinants of the
// bases in checker/formulas/equations.* by an exact polynomial identity), and the sphere point p = 1
// in exact arithmetic over Q(sqrt2).
#pragma once
#include <gmpxx.h>

#include <string>

#include "checker/formulas/equations.hpp"

namespace superpack_checker {

// A function of p on a p interval with an enclosure of its p-derivative there.
struct ValueAndSlope {
    Real value, slope;
};

// Digamma on x > 0 (increasing there), from mpfr_digamma at the endpoints.
Real digamma(const Real& x);

// t = 2^(-1/(2p)), t' = t ln2 / (2p^2).
ValueAndSlope halving_shift(const Real& p);
// V_sb(p) and V_sb'(p) = V_sb(p) (-3/(2p^2)) (psi(1 + 1/(2p)) - psi(1 + 3/(2p))).
ValueAndSlope superball_volume_with_slope(const Real& p);
// c = (1 - 2^(1-2p))^(1/(2p)) (Eq. 5) and c' = c (2 ln2 2^(1-2p) / (2p u) - ln u / (2p^2)), u = 1 - 2^(1-2p).
ValueAndSlope octahedral_height_with_slope(const Real& p);

// df/ds of Eq. 2 (C0) or Eq. 9 (C1) for s >= 0, written so that it is visibly positive:
// 2p ((s + t)^(2p-1) + k s^(2p-1)), k = 1 (C0) or 2 (C1). With s >= 0 and t > 0 every term is
// >= 0 and the first > 0, so f is increasing on s >= 0 and its one root there is s(p).
Real cubic_slope_in_s(const CubicEquation& equation, const Real& s);
// df/dp at fixed s > 0:
//   C0: (s+t)^(2p) (2 ln(s+t) + 2p t'/(s+t)) + s^(2p) 2 ln s - 2 ln2 2^(-2p)
//   C1: (s+t)^(2p) (2 ln(s+t) + 2p t'/(s+t)) + 2 s^(2p) 2 ln s
Real cubic_slope_in_p(const CubicEquation& equation, const Real& s);
// s(p) with ds/dp = -f_p / f_s (implicit function theorem; f_s > 0 on s > 0), given an
// enclosure s of the root for every p of equation.p.
ValueAndSlope cubic_root_with_slope(const CubicEquation& equation, const Real& s);

// |det B| in closed form: C0 (Eq. 1) det = -8t(2s + t), C1 (Eq. 8) det = 8t^2(3s + t), O0 (Eq. 5)
// det = 8c; with their p-derivatives from those of s, t and c.
ValueAndSlope cubic_abs_determinant(bool c1, const ValueAndSlope& s, const ValueAndSlope& t);
ValueAndSlope octahedral_abs_determinant(const ValueAndSlope& c);
// Proves the three closed forms above equal to determinant(c0_basis(s, t)), determinant(c1_basis(s, t))
// and determinant(o0_basis(c)) as polynomials: each side has degree <= 3 in each variable, so
// agreement on the grid {0,1,2,3}^2 (exact in point intervals) is equality everywhere.
// Returns an empty string, or the first grid point that disagrees.
std::string determinant_identity_failure(mpfr_prec_t precision);

// phi = V / d and phi' = (V' d - V d') / d^2.
ValueAndSlope density_with_slope(const ValueAndSlope& volume, const ValueAndSlope& abs_determinant);

// h = 2 s0 + t - 3 t s1 - t^2, with |det B_C0| - |det B_C1| = 8t h (closed forms above). So
// phi_C1 - phi_C0 = V (|det B_C0| - |det B_C1|) / (|det B_C0| |det B_C1|) has the sign of h and
// the same zeros: the crossover is a root of h, and V drops out of the sign proof.
ValueAndSlope cubic_crossover_function(const ValueAndSlope& s0, const ValueAndSlope& s1, const ValueAndSlope& t);

// a + b sqrt2 with rational a, b: the exact values at the sphere point p = 1.
struct Surd {
    mpq_class a, b;
};
Surd operator+(const Surd& x, const Surd& y);
Surd operator-(const Surd& x, const Surd& y);
Surd operator*(const Surd& x, const Surd& y);
int sign(const Surd& x);
bool operator==(const Surd& x, const Surd& y);
// At p = 1 (so 2p = 2 and t = 2^(-1/2) = sqrt2/2): Eq. 2 is (s+t)^2 + s^2 + 1/4 - 1, Eq. 9 is
// (s+t)^2 + 2 s^2 - 1, and h as above.
Surd sphere_point_shift();
Surd sphere_point_cubic_equation(bool c1, const Surd& s);
Surd sphere_point_crossover_function(const Surd& s0, const Surd& s1);

}  // namespace superpack_checker
