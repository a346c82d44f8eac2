// The overlap test of a concave superball K = {sum |x_i|^q <= 1}, q = 2p <= 1, and K + v for an
// exact rational v, written again for the checker (NOTES.md 13.4 and 13.5): by the difference-body
// lemma the interiors meet iff for some coordinate k and some split of the others into S and T,
// A_S < 1, A_T < 1 and (1 - A_S)^(1/q) + (1 - A_T)^(1/q) > |v_k|, with A_S = sum_(i in S) |v_i|^q.
#pragma once
#include <mpfr.h>

#include "checker/formulas/equations_lattice.hpp"

namespace superpack_checker {

enum class StarVerdict { disjoint, overlapping, undecided };

// disjoint: every case certainly fails (a coordinate with |v_i| >= 1, decided exactly, fails its
// cases without rounding); overlapping: one case certainly holds; else undecided.
StarVerdict star_cases(const RationalVector& v, const mpq_class& q, mpfr_prec_t precision);

}  // namespace superpack_checker
