// The proof of a simulation's end state (NOTES.md 14.2): its floating-point cell, centres and
// orientations rounded to exact rationals, then proved a packing by certify_periodic_packing.
// The state comes as plain numbers because problems/ does not see sim/, which made it; the
// caller's NormalGuess (sim's separating planes) only guides the proof.
#pragma once
#include <array>
#include <vector>

#include "superpack/problems/periodic/periodic_packing.hpp"

namespace superpack {

// Particle i is centred at fractional[i] . cell and turned by R(quaternions[i]).
struct SimulationEndState {
    std::array<std::array<double, 3>, 3> cell;       // rows: the period vectors
    std::vector<std::array<double, 3>> fractional;   // centres in cell coordinates
    std::vector<std::array<double, 4>> quaternions;  // (w, x, y, z)
};

// The end state rounded (cell entries and fractional coordinates to multiples of 2^-40,
// quaternion components to 2^-30: any nonzero rational quaternion is a rotation) and proved.
PeriodicCertificate<DInterval> prove_end_state(const Rational& p, const SimulationEndState& end, const NormalGuess& guess);

}  // namespace superpack
