#include "critical_linear.hpp"

#include <algorithm>
#include <cmath>

namespace superpack {

namespace {

double determinant3(const Matrix3& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

}  // namespace

Vector3 solve3(const Matrix3& m, const Vector3& r) {
    const double d = determinant3(m);
    double scale = 0;
    for (const Vector3& row : m)
        for (double x : row) scale = std::max(scale, std::fabs(x));
    if (!(std::fabs(d) > 1e-12 * scale * scale * scale)) return {0, 0, 0};
    Vector3 y{};
    for (int i = 0; i < 3; ++i) {
        Matrix3 a = m;
        for (int k = 0; k < 3; ++k) a[k][i] = r[k];
        y[i] = determinant3(a) / d;
    }
    return y;
}

}  // namespace superpack
