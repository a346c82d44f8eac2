#include "superpack/sim/random_source.hpp"

#include <cmath>

namespace superpack::sim {

Vector3 RandomSource::unit_vector() {
    for (;;) {
        const double a = uniform(-1, 1), b = uniform(-1, 1), s = a * a + b * b;
        if (s >= 1 || s == 0) continue;
        const double root = std::sqrt(1 - s);
        return {2 * a * root, 2 * b * root, 1 - 2 * s};
    }
}

Quaternion RandomSource::rotation() {
    const double u = uniform(), v = uniform() * 2 * M_PI, w = uniform() * 2 * M_PI;
    const double a = std::sqrt(1 - u), b = std::sqrt(u);
    return Quaternion{a * std::sin(v), a * std::cos(v), b * std::sin(w), b * std::cos(w)};
}

}  // namespace superpack::sim
