#include "superpack/sim/periodic_configuration.hpp"

#include <cmath>
#include <stdexcept>

#include "superpack/sim/periodic_images.hpp"

namespace superpack::sim {

double PeriodicConfiguration::volume() const { return std::abs(determinant(cell)); }

double superball_volume(double p) {
    const double inverse = 1 / (2 * p);
    return 8 * std::exp(3 * std::lgamma(1 + inverse) - std::lgamma(1 + 3 * inverse));
}

double density(const SuperballShape& shape, const PeriodicConfiguration& configuration) {
    return static_cast<double>(configuration.size()) * superball_volume(shape.p()) / configuration.volume();
}

Vector3 nearest_difference(const PeriodicConfiguration& configuration, std::size_t i, std::size_t j) {
    Vector3 difference = configuration.fractional[j] - configuration.fractional[i];
    for (double& x : difference) x -= std::floor(x + 0.5);
    return row_combination(configuration.cell, difference);
}

namespace {

bool meets(const SuperballShape& shape, const PeriodicConfiguration& configuration, std::size_t i, std::size_t j) {
    const double cutoff = 2 * shape.circumradius();
    const Vector3 difference = nearest_difference(configuration, i, j);
    const Placement first{Vector3{0, 0, 0}, rotation_matrix(configuration.orientations[i])};
    Placement second{Vector3{0, 0, 0}, rotation_matrix(configuration.orientations[j])};
    for (const auto& shift : image_shifts(configuration.cell, difference, cutoff)) {
        if (i == j && shift == std::array<int, 3>{0, 0, 0}) continue;
        second.center = difference + row_combination(configuration.cell, Vector3{double(shift[0]), double(shift[1]), double(shift[2])});
        if (overlapping(shape, first, second)) return true;
    }
    return false;
}

}  // namespace

bool particle_overlaps(const SuperballShape& shape, const PeriodicConfiguration& configuration, std::size_t i) {
    for (std::size_t j = 0; j < configuration.size(); ++j)
        if (meets(shape, configuration, i, j)) return true;
    return false;
}

bool any_overlap(const SuperballShape& shape, const PeriodicConfiguration& configuration) {
    for (std::size_t i = 0; i < configuration.size(); ++i)
        for (std::size_t j = i; j < configuration.size(); ++j)
            if (meets(shape, configuration, i, j)) return true;
    return false;
}

PeriodicConfiguration lattice_configuration(const Matrix3& basis, int particles, double expansion) {
    if (particles < 1) throw std::invalid_argument("lattice_configuration: needs at least one particle");
    // The factorisation n1 >= n2 >= n3 of n with the smallest n1, then the smallest n2.
    std::array<int, 3> counts{particles, 1, 1};
    for (int a = 1; a <= particles; ++a)
        for (int b = 1; b <= a; ++b) {
            if (particles % (a * b) != 0) continue;
            const int c = particles / (a * b);
            if (c > b) continue;
            if (a < counts[0] || (a == counts[0] && b < counts[1])) counts = {a, b, c};
        }
    PeriodicConfiguration configuration;
    for (int row = 0; row < 3; ++row) configuration.cell[row] = (expansion * counts[row]) * basis[row];
    for (int a = 0; a < counts[0]; ++a)
        for (int b = 0; b < counts[1]; ++b)
            for (int c = 0; c < counts[2]; ++c) {
                configuration.fractional.push_back({double(a) / counts[0], double(b) / counts[1], double(c) / counts[2]});
                configuration.orientations.push_back(Quaternion{});
            }
    return configuration;
}

PeriodicConfiguration random_configuration(const SuperballShape& shape, int particles, double phi, RandomSource& random) {
    if (particles < 1) throw std::invalid_argument("random_configuration: needs at least one particle");
    const double side = std::cbrt(particles * superball_volume(shape.p()) / phi);
    PeriodicConfiguration configuration;
    configuration.cell = {Vector3{side, 0, 0}, Vector3{0, side, 0}, Vector3{0, 0, side}};
    for (int i = 0; i < particles; ++i) {
        for (long trial = 0;; ++trial) {
            if (trial == 100000)
                throw std::runtime_error("random_configuration: no room found for particle " + std::to_string(i + 1) + " at this density");
            configuration.fractional.push_back({random.uniform(), random.uniform(), random.uniform()});
            configuration.orientations.push_back(random.rotation());
            if (!particle_overlaps(shape, configuration, configuration.size() - 1)) break;
            configuration.fractional.pop_back();
            configuration.orientations.pop_back();
        }
    }
    return configuration;
}

void wrap(PeriodicConfiguration& configuration) {
    for (auto& f : configuration.fractional)
        for (double& x : f) x -= std::floor(x);
}

void reduce_cell(PeriodicConfiguration& configuration) {
    Matrix3& rows = configuration.cell;
    for (bool changed = true; changed;) {
        changed = false;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                if (i == j) continue;
                const double m = std::round(dot(rows[i], rows[j]) / dot(rows[j], rows[j]));
                if (m == 0) continue;
                const Vector3 shorter = rows[i] - m * rows[j];
                if (dot(shorter, shorter) >= dot(rows[i], rows[i]) * (1 - 1e-12)) continue;
                // b_i = b_i' + m b_j, so x = ... + f_i b_i' + (f_j + m f_i) b_j + ...
                rows[i] = shorter;
                for (auto& f : configuration.fractional) f[j] += m * f[i];
                changed = true;
            }
    }
    wrap(configuration);
}

}  // namespace superpack::sim
