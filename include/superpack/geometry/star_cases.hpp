// The overlap test of K and K + v in closed form, for a superball with 2p <= 1 (NOTES.md 13.5):
// by the difference-body lemma of NOTES.md 13.4 the interiors meet iff, for some coordinate k and
// some split of the others into S and T,
//
//     A_S < 1,  A_T < 1  and  (1 - A_S)^(1/q) + (1 - A_T)^(1/q) > |v_k|,   A_S = sum_(i in S) |v_i|^q,
//
// q = 2p: d 2^(d-1) cases (12 in 3-D, 4 in 2-D). Each is decided with intervals, so an answer
// holds for every v in the box:
//   - proved (disjoint): every case certainly fails;
//   - refuted (they meet): some case certainly holds; no witness point comes with it;
//   - undecided: a case at its threshold within the enclosures (boundaries that touch).
// A term with |v_i| >= 1 makes A_S >= 1 exactly, by monotonicity, without the power's rounding:
// so tips that meet arms or tips, as v = (1, 1, 0), are decided, which no box cover can do; and a
// coordinate with |v_k| >= 2 parts the cubes [-1, 1]^d and v + [-1, 1]^d (proved at once).
#pragma once
#include <vector>

#include "superpack/arith/outcome.hpp"
#include "superpack/geometry/body.hpp"

namespace superpack {

// Throws InputError unless v has the body's dimension and 2p <= 1 (the lemma needs q <= 1).
template <class I>
Outcome star_disjoint_by_cases(const Superball& body, const std::vector<I>& v);

}  // namespace superpack
