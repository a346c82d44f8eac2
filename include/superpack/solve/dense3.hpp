// Vectors and 3x3 matrices in binary64: the one small dense linear algebra of the floating-point
// guesses (the simulation layer, the pictures of render/, the lattice search; the critical search
// takes its types).
// Guesses only: a packing or a bound is proved elsewhere with intervals, so plain doubles in
// round-to-nearest are what they need: small, inline, and nothing clever.
//
// Our own header rather than Eigen's fixed-size types, for two reasons: a translation unit of a
// few 3x3 operations with <Eigen/Dense> took 1.9 s to compile, with this header 0.28 s (g++ 12
// -O3, measured 2026-12-07), and Eigen is kept to the one file that computes preconditioners
// (scripts/check-layers.py); and every guess must stay bit for bit what it was, which needs the
// operations in the order written here.
//
// The functions live in their own namespace, `dense`: in namespace superpack a non-template
// determinant(Matrix3) would silently take the place of geometry's determinant(Basis<T>) for a
// Basis<double> (another formula, other roundings). Callers name what they use.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace superpack::dense {

using Vector3 = std::array<double, 3>;
// A matrix as its three rows.
using Matrix3 = std::array<Vector3, 3>;

inline Vector3 operator+(const Vector3& a, const Vector3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vector3 operator-(const Vector3& a, const Vector3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vector3 operator-(const Vector3& a) { return {-a[0], -a[1], -a[2]}; }
inline Vector3 operator*(double s, const Vector3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const Vector3& a, const Vector3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
// std::hypot, so that a vector of tiny or huge entries does not underflow or overflow its square.
inline double norm(const Vector3& a) { return std::hypot(a[0], a[1], a[2]); }
inline Vector3 cross(const Vector3& a, const Vector3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double max_abs(const Vector3& a) { return std::fmax(std::fabs(a[0]), std::fmax(std::fabs(a[1]), std::fabs(a[2]))); }
// The same but by std::max, as the lattice search and the chart's images have always taken it:
// the two differ only when a[0] is NaN (then this is NaN, max_abs the largest other entry).
inline double max_norm(const Vector3& a) { return std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])}); }

inline Matrix3 identity_matrix() { return {Vector3{1, 0, 0}, Vector3{0, 1, 0}, Vector3{0, 0, 1}}; }

inline Matrix3 transpose(const Matrix3& m) {
    return {Vector3{m[0][0], m[1][0], m[2][0]}, Vector3{m[0][1], m[1][1], m[2][1]}, Vector3{m[0][2], m[1][2], m[2][2]}};
}

// m v. By value, not by const reference: Matrix3 and Vector3 are std::arrays, so
// argument-dependent lookup also finds std::apply (wherever <tuple> is included), whose
// forwarding references would beat const references for an rvalue argument and then fail to
// compile. By value, the two tie and the non-template wins.
inline Vector3 apply(Matrix3 m, Vector3 v) { return {dot(m[0], v), dot(m[1], v), dot(m[2], v)}; }

// k0 rows[0] + k1 rows[1] + k2 rows[2] (= rows^T k): the point of a cell or lattice with
// coordinates k in the basis of its rows.
inline Vector3 row_combination(const Matrix3& rows, const Vector3& k) {
    Vector3 result{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) result[j] += k[i] * rows[i][j];
    return result;
}

// m^T v: a rotation's inverse, space coordinates to body coordinates.
inline Vector3 apply_transpose(const Matrix3& m, const Vector3& v) { return row_combination(m, v); }

// a b.
inline Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
    Matrix3 result{};
    for (int i = 0; i < 3; ++i) result[i] = row_combination(b, a[i]);  // row i of a b = a_i b
    return result;
}

inline double determinant(const Matrix3& m) { return dot(m[0], cross(m[1], m[2])); }

// The inverse by cofactors: its columns are the cross products of pairs of rows over the
// determinant. Throws std::invalid_argument when the determinant is 0 or not finite.
inline Matrix3 inverse(const Matrix3& m) {
    const double det = determinant(m);
    if (!(det != 0) || !std::isfinite(det)) throw std::invalid_argument("inverse: singular or non-finite matrix");
    const Vector3 c0 = (1 / det) * cross(m[1], m[2]), c1 = (1 / det) * cross(m[2], m[0]), c2 = (1 / det) * cross(m[0], m[1]);
    return transpose(Matrix3{c0, c1, c2});
}

}  // namespace superpack::dense
