// The closing regions of a critical-lattice certificate (NOTES.md 12.4), replayed once each: a
// box R of bases around a certified critical lattice B* on which every basis with the region's
// six contacts on bd(2K) has det >= det B* >= T, and the images of R in the chart (W, P) that
// let a chart box close by mapping into R.
//
// Replay of proof.regions[r]:
//   1. the KKT point (B*, mu*) of the contact pairs by Krawczyk (kkt_point.hpp);
//   2. B* inside R, det B* certainly > 0 and T <= the lower end of det B*;
//   3. the Hessian of the augmented Lagrangian L(B) = det B - sum mu*_i (n_i - 2) + rho/2
//      sum (n_i - 2)^2 over R, certainly positive definite by interval Cholesky
//      (positive_definite.hpp): the KKT Jacobian's rows and columns 0..8 at
//      (R, mu* - rho (n(R) - 2)) plus rho A^T A, A the constraint rows. Then L is convex on the convex R and stationary at B* in R, so
//      det B = L(B) >= L(B*) = det B* wherever all n_i(B) = 2 (the lemma of 12.4);
//   4. each image: an integral W^-1 of det +-1 (so W is integral), a signed permutation P, and
//      the configuration's six triples t with t W = +-c for the six contacts c, one each. Then a
//      chart basis B = W U P has the configuration's vectors on bd(2K) iff U has the region's
//      contacts there, and |det B| = det U. (So only a region of six pairs has images; one of
//      seven, such as D14's, is replayed and stated but closes nothing.)
#pragma once
#include <string>
#include <vector>

#include "checker/core/replay.hpp"
#include "checker/formulas/chart_forms.hpp"

namespace superpack_checker {

struct ClosingRegion {
    std::vector<Triple> contacts;
    Box box;  // R: the nine entries b_kj, row-major
};

struct ChartImage {
    Configuration configuration = Configuration::a3;
    std::array<Triple, 3> inverse{};  // the rows of W^-1
    std::array<int, 3> perm{}, sign{};
    std::size_t region = 0;
};

struct ClosingRegions {
    std::vector<ClosingRegion> regions;
    std::vector<ChartImage> images;  // all regions' images, in order (the 'c' leaves' indices)
};

// proof.regions at `path`, at the exact p and threshold T (a point).
ClosingRegions replay_closing_regions(Context& context, const Json& list, const std::string& path, const mpq_class& p,
                                      const Real& threshold);

// U = W^-1 B P^-1 (rows u_r = combination(B, inverse[r]), U[r][perm[j]] = sign[j] u_r[j]) inside R.
bool maps_into_region(const ChartImage& image, const ClosingRegion& region, const Matrix3& basis);

}  // namespace superpack_checker
