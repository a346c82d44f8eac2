// A lattice basis with interval entries (rows are the basis vectors) and its determinant.
#pragma once
#include <array>

#include "superpack/arith/interval.hpp"

namespace superpack {

template <class T>
using Basis = std::array<std::array<T, 3>, 3>;

template <class T>
T determinant(const Basis<T>& b) {
    return b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
           b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
           b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
}

}  // namespace superpack
