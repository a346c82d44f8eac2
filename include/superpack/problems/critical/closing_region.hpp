// A closing region around a certified local minimiser of |det| (NOTES.md 12.4): a box R of
// bases around the critical lattice B* on which every basis with the same contacts on bd(2K)
// has det B >= det B*. With mu* the KKT multipliers and rho >= 0, the augmented Lagrangian
//     L(B) = det B - sum_i mu*_i (n_i(B) - 2) + rho/2 sum_i (n_i(B) - 2)^2,   n_i = ||c_i B||_(2p),
// equals det B where every n_i = 2, is stationary at B* (the KKT equations), and is convex on R
// when its Hessian is positive definite at every point of R. Then L(B) >= L(B*) = det B* on R.
// The Hessian is the Jacobian of grad L(B) = (stationarity rows of kkt_equations at
// (B, mu* - rho (n(B) - 2))), enclosed over the whole box R and over the multipliers' box, and
// proved positive definite by interval Cholesky. So this is the second-order condition of
// certify_local_optimum made to hold on a region, not only at the point.
#pragma once
#include <string>
#include <vector>

#include "superpack/problems/optimality/local_optimality.hpp"

namespace superpack {

template <class I>
struct ClosingRegion {
    Outcome verdict = Outcome::undecided;  // proved: det >= det B* on R for bases with the contacts
    std::string reason;
    std::vector<Coefficients> contacts;  // the active triples, one per pair (the optimum's)
    Basis<I> center;                     // the root box of B* (det > 0)
    Basis<I> region;                     // R, which contains center
    std::vector<I> multipliers;          // the root box of mu*
    I determinant;                       // an enclosure of det B* (> 0)
    double rho = 0;
    double radius = 0;                   // R is center widened by radius (absolute) in each entry
};

// From a certified local optimum (certify_local_optimum's verdict proved), the widest region
// among radius = first_radius, first_radius / 4, ... (at most `attempts`) whose Hessian is proved
// positive definite for some rho in {0, 1, 10, ..., 10^4}. Undecided, with the reason, if none.
template <class I>
ClosingRegion<I> certify_closing_region(const LocalOptimum<I>& optimum, const I& p, double first_radius, int attempts);

// Whether every entry of `basis` lies inside the region (then the region's claim holds there).
template <class I>
bool region_contains(const ClosingRegion<I>& region, const Basis<I>& basis);

}  // namespace superpack
