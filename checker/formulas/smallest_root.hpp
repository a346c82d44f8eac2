// The smallest positive root s(p) of Eq. 2 (C0) or Eq. 9 (C1), for every p of an interval,
// from a stored Newton box: interval Newton with p as an interval parameter proves exactly one
// root in the box for each p, and f increasing on [0, upper end of the box] (df/ds > 0 there,
// checked in the checker's arithmetic) leaves no root below it. Shared by the crossover and
// slope claim kinds.
#pragma once
#include "checker/formulas/equations.hpp"
#include "checker/verifier.hpp"

namespace superpack_checker {

// node: {"box": X} (and "kind", "family", read by the caller) with, optionally, the producer's "midpoint", "derivative", "image" (each
// must contain the checker's) and "root" (must hold the checker's tightened root). Returns an
// enclosure of s(p) for every p of equation.p, tightened by further Newton steps.
Real replay_smallest_root(Context& context, const CubicEquation& equation, const Json& node, const std::string& path);

// Tightens `box`, known to hold exactly one root for every p of an interval containing
// equation.p, by Newton steps X <- N(X) ∩ X (the root stays in every iterate). Empty means
// the premise was false: std::domain_error.
Real refine_known_root(const CubicEquation& equation, const Real& box);

}  // namespace superpack_checker
