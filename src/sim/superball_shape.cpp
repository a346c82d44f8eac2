#include "superpack/sim/superball_shape.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace superpack::sim {

SuperballShape::SuperballShape(double p) : p_(p) {
    if (!std::isfinite(p) || !(p >= 0.5))
        throw std::invalid_argument("SuperballShape: needs a finite p >= 1/2 (a convex superball), got " + std::to_string(p));
    q_ = 2 * p;
    inverse_q_ = 1 / q_;
    const bool octahedron = q_ == 1;
    r_minus_one_ = octahedron ? std::numeric_limits<double>::infinity() : 1 / (q_ - 1);
    r_ = octahedron ? std::numeric_limits<double>::infinity() : q_ / (q_ - 1);
    inverse_r_ = (q_ - 1) / q_;  // q - 1 is exact (Sterbenz) near q = 1
    circumradius_ = p <= 1 ? 1.0 : std::pow(3.0, 0.5 - inverse_q_);
    inradius_ = p >= 1 ? 1.0 : std::pow(3.0, 0.5 - inverse_q_);
}

double SuperballShape::gauge_power(const Vector3& x) const {
    return std::pow(std::fabs(x[0]), q_) + std::pow(std::fabs(x[1]), q_) + std::pow(std::fabs(x[2]), q_);
}

double SuperballShape::gauge(const Vector3& x) const {
    const double scale = max_abs(x);
    if (!(scale > 0)) return 0;
    double sum = 0;
    for (double xi : x) sum += std::pow(std::fabs(xi) / scale, q_);  // in [1, 3]
    return scale * std::pow(sum, inverse_q_);
}

Vector3 SuperballShape::support_point(const Vector3& direction) const {
    const double scale = max_abs(direction);
    if (!(scale > 0)) return {0, 0, 0};
    if (std::isinf(r_)) {
        // The first largest |n_k|: ties go to the lower index, the same way for n and -n.
        int k = 0;
        for (int i = 1; i < 3; ++i)
            if (std::fabs(direction[i]) > std::fabs(direction[k])) k = i;
        Vector3 vertex{0, 0, 0};
        vertex[k] = direction[k] > 0 ? 1.0 : -1.0;
        return vertex;
    }
    // t_i = |n_i| / max|n_j| in [0, 1]; x_i = sign(n_i) t_i^(r-1) / S^(1/q) with
    // S = sum t_i^r in [1, 3], since (r - 1) / r = 1/q.
    Vector3 powered{};
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
        const double t = std::fabs(direction[i]) / scale;
        powered[i] = std::pow(t, r_minus_one_);
        sum += powered[i] * t;  // t^r
    }
    const double divisor = std::pow(sum, inverse_q_);
    Vector3 point{};
    for (int i = 0; i < 3; ++i) point[i] = std::copysign(powered[i] / divisor, direction[i]);  // t = 0 gives 0
    return point;
}

double SuperballShape::support_value(const Vector3& direction) const {
    const double scale = max_abs(direction);
    if (!(scale > 0)) return 0;
    if (std::isinf(r_)) return scale;
    double sum = 0;
    for (double n : direction) sum += std::pow(std::fabs(n) / scale, r_);
    return scale * std::pow(sum, inverse_r_);
}

}  // namespace superpack::sim
