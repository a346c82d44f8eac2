// Orientations of the simulation's particles as quaternions, composed without drift (a product
// renormalized now and then stays a rotation, where a product of matrices slowly would not).
#pragma once
#include "superpack/sim/vector3.hpp"

namespace superpack::sim {

// w + x i + y j + z k; the default is the identity rotation.
struct Quaternion {
    double w = 1, x = 0, y = 0, z = 0;
};

// q / |q|; throws std::invalid_argument for q = 0 or a non-finite q.
Quaternion normalized(const Quaternion& q);

// The Hamilton product a b: the rotation b first, then a.
Quaternion multiply(const Quaternion& a, const Quaternion& b);

// The rotation v -> q v q^-1 as a matrix, for any nonzero q: the homogeneous formula divided
// by |q|^2, so that a quaternion a few ulps off unit length still gives a rotation to rounding.
// It maps body coordinates to space coordinates. Throws std::invalid_argument for q = 0.
Matrix3 rotation_matrix(const Quaternion& q);

// The rotation by `angle` (radians, right-handed) about `unit_axis`.
Quaternion axis_angle(const Vector3& unit_axis, double angle);

}  // namespace superpack::sim
