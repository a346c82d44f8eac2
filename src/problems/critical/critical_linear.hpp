// 3 x 3 floating-point linear algebra for the guesses of the branch and bound (the Lagrangian's
// multipliers, the contractor's preconditioner): any result is sound to use, since what a box's
// reason proves never depends on these values, only its sharpness does.
#pragma once
#include "superpack/solve/dense3.hpp"

namespace superpack {

using dense::Matrix3;
using dense::Vector3;

// Cramer's rule for m y = r; zero when m is nearly singular.
Vector3 solve3(const Matrix3& m, const Vector3& r);

}  // namespace superpack
