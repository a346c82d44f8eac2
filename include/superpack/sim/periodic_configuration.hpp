// N rotated superballs in a triclinic periodic cell: the state of the packing optimizer
// (sim/shrinking_cell.hpp). Floating point only: it guesses a packing, which problems/ then
// proves or scales until it can prove it.
#pragma once
#include <cstddef>
#include <vector>

#include "superpack/sim/overlap.hpp"
#include "superpack/sim/quaternion.hpp"
#include "superpack/sim/random_source.hpp"
#include "superpack/sim/superball_shape.hpp"
#include "superpack/sim/vector3.hpp"

namespace superpack::sim {

struct PeriodicConfiguration {
    Matrix3 cell;                          // rows: the three period vectors
    std::vector<Vector3> fractional;       // centres in cell coordinates, each in [0, 1)
    std::vector<Quaternion> orientations;  // unit; particle i is center(i) + R(q_i) K
    std::size_t size() const { return fractional.size(); }
    Vector3 center(std::size_t i) const { return row_combination(cell, fractional[i]); }
    Placement placement(std::size_t i) const { return {center(i), rotation_matrix(orientations[i])}; }
    double volume() const;
};

// Volume of K, 8 Gamma(1 + 1/(2p))^3 / Gamma(1 + 3/(2p)), in floating point (lgamma, so that
// large p does not overflow): for the optimizer's running density only.
double superball_volume(double p);
double density(const SuperballShape& shape, const PeriodicConfiguration& configuration);

// The shortest difference vector of the centres of j and i modulo the cell's lattice (its
// fractional coordinates reduced to [-1/2, 1/2)).
Vector3 nearest_difference(const PeriodicConfiguration& configuration, std::size_t i, std::size_t j);

// Does particle i meet another particle, or a periodic image of itself or of another, in
// interior points (floating-point judgement, sim/overlap.hpp)? Every image whose centre lies
// within twice the circumradius is tested.
bool particle_overlaps(const SuperballShape& shape, const PeriodicConfiguration& configuration, std::size_t i);
bool any_overlap(const SuperballShape& shape, const PeriodicConfiguration& configuration);

// The lattice with basis rows `basis` as a cell of n particles: the supercell n1 b1, n2 b2,
// n3 b3 with n1 n2 n3 = n and n1 >= n2 >= n3 as close as possible, the particles unrotated at
// the lattice points, every length then times `expansion` (an unsaturated start, the paper's
// route).
PeriodicConfiguration lattice_configuration(const Matrix3& basis, int particles, double expansion);

// n particles at random positions and orientations in a cube at density `phi`, inserted one at
// a time with overlapping trials rejected; throws std::runtime_error if 10^5 trials in a row
// fail (phi too high for random insertion).
PeriodicConfiguration random_configuration(const SuperballShape& shape, int particles, double phi, RandomSource& random);

// Fractional coordinates back into [0, 1).
void wrap(PeriodicConfiguration& configuration);

// Replaces the period vectors by a shorter basis of the same lattice (pairwise size
// reduction until no step shortens one), carrying the fractional coordinates along, so that a
// cell sheared by many deformations keeps few images within the cutoff.
void reduce_cell(PeriodicConfiguration& configuration);

}  // namespace superpack::sim
