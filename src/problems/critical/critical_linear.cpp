#include "critical_linear.hpp"

#include <algorithm>
#include <cmath>

#include "superpack/geometry/lattice_basis.hpp"

namespace superpack {

// Determinants by geometry's cofactor expansion (lattice_basis.hpp), the one formula of a basis.
Vector3 solve3(const Matrix3& m, const Vector3& r) {
    const double d = determinant(m);
    double scale = 0;
    for (const Vector3& row : m)
        for (double x : row) scale = std::max(scale, std::fabs(x));
    if (!(std::fabs(d) > 1e-12 * scale * scale * scale)) return {0, 0, 0};
    Vector3 y{};
    for (int i = 0; i < 3; ++i) {
        Matrix3 a = m;
        for (int k = 0; k < 3; ++k) a[k][i] = r[k];
        y[i] = determinant(a) / d;
    }
    return y;
}

}  // namespace superpack
