// The adaptive shrinking cell (Torquato & Jiao, Phys. Rev. E 80, 041104 (2009)), the
// stochastic optimizer of the paper's Sec. II: particle positions, orientations and the cell's
// period vectors are the design variables. A cycle tries a translation and a rotation of each
// particle, then one deformation of the cell (a random symmetric strain, the fractional
// coordinates kept); a trial is kept when no two particles overlap, and a trial that grows the
// cell must also pass an isobaric Metropolis test at a pressure that rises through the run (so
// the start anneals, and the end only compresses). Step sizes follow the acceptance rates; the
// densest state met is the result. Floating point only: the end state is a guess that
// problems/periodic/periodic_packing.hpp proves, or scales up until it can.
#pragma once
#include <cstdint>
#include <functional>

#include "superpack/sim/periodic_configuration.hpp"

namespace superpack::sim {

struct ShrinkingCellOptions {
    long cycles = 20000;
    std::uint64_t seed = 1;
    // The reduced pressure P v_K / kT rises geometrically from start to end over this fraction
    // of the cycles; after it, only compressions are tried. At pressure P a cell of N bodies at
    // density phi fluctuates in volume by about 1 / (P phi sqrt N) relative: 10 lets a random
    // start order itself, 1000 keeps a lattice start a crystal (at 10 it melts and jams lower).
    double start_pressure = 10, end_pressure = 1e7, annealed_fraction = 0.8;
};

struct ShrinkingCellProgress {
    long cycle = 0;
    double phi = 0;
};

struct ShrinkingCellResult {
    PeriodicConfiguration configuration;
    double start_phi = 0, phi = 0;  // floating-point densities of the start and the end
    long cycles = 0;
    double particle_acceptance = 0, cell_acceptance = 0;  // over the whole run
};

// Runs the optimizer from `start` (which must be free of overlaps: std::invalid_argument
// otherwise). `progress`, if given, is called about every 1000 cycles.
ShrinkingCellResult shrink_cell(const SuperballShape& shape, PeriodicConfiguration start, const ShrinkingCellOptions& options,
                                const std::function<void(const ShrinkingCellProgress&)>& progress = {});

}  // namespace superpack::sim
