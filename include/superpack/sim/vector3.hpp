// sim's names for the dense linear algebra of the floating-point guesses (solve/dense3.hpp):
// the simulation writes dot(a, b), not dense::dot(a, b).
#pragma once
#include "superpack/solve/dense3.hpp"

namespace superpack::sim {

using dense::apply;
using dense::apply_transpose;
using dense::cross;
using dense::determinant;
using dense::dot;
using dense::identity_matrix;
using dense::inverse;
using dense::Matrix3;
using dense::max_abs;
using dense::multiply;
using dense::norm;
using dense::row_combination;
using dense::transpose;
using dense::Vector3;
using dense::operator+;
using dense::operator-;
using dense::operator*;

}  // namespace superpack::sim
