// The periodic images of one particle that can reach another: in a triclinic cell whose period
// vectors are the rows of `cell`, the integer shifts k with |delta + k0 b0 + k1 b1 + k2 b2|
// below a cutoff (twice the circumradius for the overlap tests).
#pragma once
#include <array>
#include <vector>

#include "superpack/sim/vector3.hpp"

namespace superpack::sim {

// Every integer k with |delta + row_combination(cell, k)| < cutoff, in lexicographic order;
// complete, since x = delta + cell^T k gives k = cell^-T (x - delta), so
// |k_m| <= |column m of cell^-1| (cutoff + |delta|), a box that is enumerated and filtered.
// Throws std::invalid_argument if the cell is singular (relative to its row lengths), an
// input is not finite, or the box would exceed 10^6 entries.
std::vector<std::array<int, 3>> image_shifts(const Matrix3& cell, const Vector3& delta, double cutoff);

}  // namespace superpack::sim
