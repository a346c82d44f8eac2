// The simulation's one source of randomness: a 64-bit Mersenne twister turned into uniform
// doubles by superpack itself, so that one seed gives one run on every standard library (the
// std:: distributions are implementation-defined; the engine is not).
#pragma once
#include <cstdint>
#include <random>

#include "superpack/sim/quaternion.hpp"
#include "superpack/sim/vector3.hpp"

namespace superpack::sim {

class RandomSource {
public:
    explicit RandomSource(std::uint64_t seed) : engine_(seed) {}
    // Uniform in [0, 1): the top 53 bits of one draw.
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
    // Each coordinate uniform in [-size, size].
    Vector3 cube_point(double size) { return {uniform(-size, size), uniform(-size, size), uniform(-size, size)}; }
    // Uniform on the unit sphere (Marsaglia's rejection from the square).
    Vector3 unit_vector();
    // A uniformly random rotation (Shoemake's subgroup algorithm).
    Quaternion rotation();
    // A rotation about a uniform axis by an angle uniform in [-angle, angle].
    Quaternion rotation_step(double angle) { return axis_angle(unit_vector(), uniform(-angle, angle)); }
    std::uint64_t below(std::uint64_t bound) { return engine_() % bound; }

private:
    std::mt19937_64 engine_;
};

}  // namespace superpack::sim
