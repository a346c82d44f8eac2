// Positive definiteness of a symmetric interval matrix by interval LDL^T: the second-order
// condition of a local optimum (claim_local_optimum.cpp) and the convexity of a closing region's
// augmented Lagrangian (critical_region.cpp) are both this one test.
#pragma once
#include <cstddef>
#include <vector>

#include "checker/core/real.hpp"

namespace superpack_checker {

// LDL^T of the symmetric interval matrix m (its lower triangle): each symmetric matrix with
// entries in m has its exact pivots inside the interval pivots, so all of them certainly > 0
// proves every such matrix positive definite. Returns the first pivot not certainly positive,
// or m.size().
std::size_t first_unproved_pivot(const std::vector<std::vector<Real>>& m);
// The same by interval Cholesky (L L^T, the pivots' square roots on the diagonal): as sound, and
// tighter where the matrix is wide, since each update subtracts a square l^2 (one interval, a
// tight square) instead of l l d (three factors, each wide on its own).
std::size_t first_unproved_cholesky_pivot(const std::vector<std::vector<Real>>& m);

}  // namespace superpack_checker
