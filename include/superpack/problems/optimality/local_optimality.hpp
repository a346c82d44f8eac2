// Local optimality of a lattice packing (issue 12, item 3; NOTES.md 11.5): a certified strict
// local minimiser of |det B| among the admissible lattices near it. The critical lattice is the
// unique solution, in a box, of the KKT system of min det B subject to ||c_i B||_(2p) = 2 for its
// contact triples c_i (Krawczyk); then every multiplier is certified positive (strict
// complementarity), H + rho A^T A is certified positive definite by interval Cholesky (H the
// Hessian of the Lagrangian in the nine entries, A the constraint Jacobian: this is the
// second-order condition on the tangent space {A d = 0}, by Finsler's lemma), and the lattice
// check proves every other lattice vector longer than 2 on the box, so nearby lattices have no
// other contact. At p = 1 rotations make the critical point non-isolated: undecided.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "superpack/geometry/lattice.hpp"
#include "superpack/problems/guess/lattice_search.hpp"
#include "superpack/solve/krawczyk.hpp"

namespace superpack {

template <class I>
struct LocalOptimum {
    Outcome verdict = Outcome::undecided;  // proved: a strict local minimiser; never refuted here
    std::string reason;
    std::vector<Coefficients> contacts;     // the contact triples, one per pair, in the basis below
    std::vector<I> search_box;              // the box of x = (B, mu) in which Krawczyk proved one KKT point
    std::optional<Basis<I>> basis;          // the critical lattice's basis (Krawczyk's root box)
    std::vector<I> multipliers;             // one per contact pair, in the order of contacts
    std::optional<I> phi;                   // V(p) / |det| of the critical lattice
    std::optional<LatticeCheck<I>> check;   // admissibility on the box, contacts by the KKT equations
    double rho = 0;                         // the weight that made H + rho A^T A positive definite
};

// The KKT system at x = (B row-major, mu_1 .. mu_m): for each entry (k, j), the cofactor of
// b_kj minus sum_i mu_i c_ik sign(u_ij) |u_ij|^(2p-1), u_i = c_i B / n_i, n_i = ||c_i B||_(2p); then
// n_i - 2. One template over the scalar (an interval, or a Jet for the Jacobian).
template <class T, class P>
std::vector<T> kkt_equations(const std::vector<T>& x, const std::vector<Coefficients>& active, const P& p);

// Krawczyk on kkt_equations in a box of relative radius 1e-9 about a floating-point KKT point
// (kkt_point), refined to the working precision: unique when the box holds exactly one KKT
// point. The first step of certify_local_optimum, and the definition of the family S6 at p
// (families.hpp), whose lattice is such a point.
template <class I>
KrawczykResult<I> isolate_kkt_point(const KktPoint& guess, const std::vector<Coefficients>& active, const I& p);

// Interval Cholesky of the symmetric matrix whose lower triangle is `m`: success (every pivot
// certainly positive) proves every symmetric matrix with entries in m positive definite (the
// second-order condition here, and on a whole region in problems/critical/closing_region.hpp).
template <class I>
bool certainly_positive_definite(const std::vector<std::vector<I>>& m);

// From a floating-point guess of the lattice (any basis of it) and its contact triples in that
// basis (one per +-pair, or both signs). A basis with det < 0 is used with b3 negated, and the
// certified basis and contacts are then in that basis.
template <class I>
LocalOptimum<I> certify_local_optimum(const DoubleBasis& guess, const std::vector<Coefficients>& contacts, const I& p);

}  // namespace superpack
