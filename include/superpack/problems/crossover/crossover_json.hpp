// The JSON form of the crossover and slope proofs: every enclosure as {"lo","hi"}, every
// p piece with its claim, reason and the enclosures that decide it, so a checker can replay.
#pragma once
#include "superpack/problems/crossover/crossover.hpp"
#include "superpack/problems/families/family_json.hpp"

namespace superpack {

Json sign_piece_json(const SignPiece& piece);
template <class I>
Json density_slope_json(const DensitySlope<I>& slope);
template <class I>
Json printed_check_json(const PrintedCheck<I>& check);
template <class I>
Json newton_json(const NewtonResult<I>& newton);
template <class I>
Json cubic_crossover_json(const CubicCrossover<I>& crossover);
template <class I>
Json octahedral_crossover_json(const OctahedralCrossover<I>& crossover);
template <class I>
Json sphere_slopes_json(const SphereSlopes<I>& slopes);

}  // namespace superpack
