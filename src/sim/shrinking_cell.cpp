#include "superpack/sim/shrinking_cell.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace superpack::sim {

namespace {

// A step size that follows its acceptance rate: larger when most trials pass, smaller when
// few do, never below `floor` (a collapsed step would freeze that kind of move for good).
struct AdaptiveStep {
    double size, floor, ceiling;
    long tried = 0, accepted = 0;
    void record(bool kept) {
        ++tried;
        accepted += kept;
    }
    void adapt() {
        if (tried == 0) return;
        const double rate = double(accepted) / double(tried);
        if (rate > 0.4) size = std::min(ceiling, size * 1.2);
        if (rate < 0.2) size = std::max(floor, size * 0.8);
        tried = accepted = 0;
    }
};

// A random symmetric strain of entries in [-size, size].
Matrix3 random_strain(RandomSource& random, double size) {
    Matrix3 strain{};
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) strain[i][j] = strain[j][i] = random.uniform(-size, size);
    return strain;
}

// The reduced pressure P v_K / kT of cycle `cycle`: from `start` up geometrically to `end` over
// the first `annealed` cycles, infinite after (only compressions are kept then).
double pressure_at(long cycle, long annealed, double start, double end) {
    if (cycle > annealed) return std::numeric_limits<double>::infinity();
    return start * std::pow(end / start, double(cycle) / double(annealed));
}

}  // namespace

ShrinkingCellResult shrink_cell(const SuperballShape& shape, PeriodicConfiguration start, const ShrinkingCellOptions& options,
                                const std::function<void(const ShrinkingCellProgress&)>& progress) {
    if (start.size() == 0) throw std::invalid_argument("shrink_cell: no particles");
    if (any_overlap(shape, start)) throw std::invalid_argument("shrink_cell: the start configuration overlaps");
    RandomSource random(options.seed);
    PeriodicConfiguration state = std::move(start);
    reduce_cell(state);
    const double length = std::cbrt(state.volume() / double(state.size()));
    AdaptiveStep translation{0.1 * length, 1e-12 * length, length}, rotation{0.1, 1e-12, M_PI}, strain{0.01, 1e-12, 0.1};
    long particle_kept = 0, particle_tried = 0, cell_kept = 0;
    const double particle_volume = superball_volume(shape.p());
    const long annealed = static_cast<long>(options.annealed_fraction * double(options.cycles));
    PeriodicConfiguration best = state;  // the densest state met (all states are free of overlaps)
    ShrinkingCellResult result;
    result.start_phi = density(shape, state);
    for (long cycle = 1; cycle <= options.cycles; ++cycle) {
        for (std::size_t i = 0; i < state.size(); ++i) {
            const Vector3 old_fraction = state.fractional[i];
            const Quaternion old_orientation = state.orientations[i];
            const Matrix3 inverse_cell = inverse(state.cell);
            state.fractional[i] = old_fraction + apply_transpose(inverse_cell, random.cube_point(translation.size));
            state.orientations[i] = normalized(multiply(random.rotation_step(rotation.size), old_orientation));
            const bool kept = !particle_overlaps(shape, state, i);
            if (!kept) {
                state.fractional[i] = old_fraction;
                state.orientations[i] = old_orientation;
            }
            translation.record(kept);
            rotation.record(kept);
            particle_kept += kept;
            ++particle_tried;
        }
        wrap(state);
        // Rows deform as b -> b (I + strain); the fractional coordinates stay, so the centres
        // move with the cell. A compression is tried for overlaps at once; an expansion first
        // passes the isobaric Metropolis test, exp(-P dV / v_K + N ln(V'/V)) (Torquato & Jiao's
        // cell moves at finite pressure), which lets a jammed state loosen and find a denser one.
        const Matrix3 old_cell = state.cell;
        Matrix3 deformation = random_strain(random, strain.size);
        for (int d = 0; d < 3; ++d) deformation[d][d] += 1;
        const double ratio = determinant(deformation);
        const double pressure = pressure_at(cycle, annealed, options.start_pressure, options.end_pressure);
        const double log_weight = -pressure * (ratio - 1) * state.volume() / particle_volume + double(state.size()) * std::log(ratio);
        if (ratio > 0 && (ratio < 1 || std::log(random.uniform()) < log_weight)) {
            state.cell = multiply(old_cell, deformation);
            const bool kept = !any_overlap(shape, state);
            if (!kept) state.cell = old_cell;
            strain.record(kept);
            cell_kept += kept;
            if (kept && ratio < 1 && state.volume() < best.volume()) best = state;
        }
        if (cycle % 50 == 0) {
            translation.adapt();
            rotation.adapt();
            strain.adapt();
            reduce_cell(state);
        }
        if (progress && cycle % 1000 == 0) progress({cycle, density(shape, state)});
    }
    reduce_cell(best);
    result.configuration = best;
    result.phi = density(shape, best);
    result.cycles = options.cycles;
    result.particle_acceptance = particle_tried ? double(particle_kept) / double(particle_tried) : 0;
    result.cell_acceptance = options.cycles ? double(cell_kept) / double(options.cycles) : 0;
    return result;
}

}  // namespace superpack::sim
