#include "superpack/sim/quaternion.hpp"

#include <cmath>
#include <stdexcept>

namespace superpack::sim {

namespace {

double squared_norm(const Quaternion& q) { return q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z; }

}  // namespace

Quaternion normalized(const Quaternion& q) {
    // hypot twice, so that neither a tiny nor a huge q loses its direction to its square.
    const double length = std::hypot(std::hypot(q.w, q.x), std::hypot(q.y, q.z));
    if (!(length > 0) || !std::isfinite(length)) throw std::invalid_argument("normalized: zero or non-finite quaternion");
    return {q.w / length, q.x / length, q.y / length, q.z / length};
}

Quaternion multiply(const Quaternion& a, const Quaternion& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Matrix3 rotation_matrix(const Quaternion& q_in) {
    const Quaternion q = normalized(q_in);  // scales, so the formula below needs |q| = 1 only
    const double w = q.w, x = q.x, y = q.y, z = q.z;
    const double n = squared_norm(q);  // 1 up to rounding; dividing by it keeps R orthogonal
    const double s = 2 / n;
    return {Vector3{(w * w + x * x - y * y - z * z) / n, s * (x * y - w * z), s * (x * z + w * y)},
            Vector3{s * (x * y + w * z), (w * w - x * x + y * y - z * z) / n, s * (y * z - w * x)},
            Vector3{s * (x * z - w * y), s * (y * z + w * x), (w * w - x * x - y * y + z * z) / n}};
}

Quaternion axis_angle(const Vector3& unit_axis, double angle) {
    const double s = std::sin(angle / 2);
    return {std::cos(angle / 2), s * unit_axis[0], s * unit_axis[1], s * unit_axis[2]};
}

}  // namespace superpack::sim
