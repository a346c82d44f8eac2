// Files people open to look at a periodic packing: extended XYZ (OVITO, ASE) with each
// particle's orientation and superquadric shape.
#pragma once
#include <string>

#include "superpack/problems/periodic/periodic_packing.hpp"

namespace superpack {

// One frame: the cell as Lattice=, positions, orientations as quaternions (x, y, z, w: OVITO's
// order) and the superquadric shape OVITO draws (aspherical_shape 1 1 1, roundness 1/p 1/p, its
// exponents 2/e = 2p). Values are the exact configuration's, printed to 17 digits.
std::string extended_xyz(const PeriodicPacking& packing, const std::string& comment);

}  // namespace superpack
