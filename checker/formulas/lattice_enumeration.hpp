// The parts of the lattice-check and star-lattice-check claims that are the same: an exact basis
// and p read from the claim and the inputs, the basis reduction R = U B replayed exactly, the
// coefficient bound of R recomputed in rationals, and every triple of its box whose vector has
// all coordinates at most 2 in size required in proof.candidates (NOTES.md 5.2, 5.6 and 13.5).
#pragma once
#include <functional>
#include <map>
#include <string>

#include "checker/core/replay.hpp"
#include "checker/formulas/equations_lattice.hpp"
#include "checker/formulas/triple.hpp"

namespace superpack_checker {

// claim.data {basis, p, packing} and inputs {basis, p}, which must agree with them.
struct LatticeClaim {
    RationalMatrix basis;
    mpq_class p;
    bool packing = false;
};
LatticeClaim read_lattice_claim(Context& context, const Json& data, const Json& inputs);

RationalMatrix read_basis(Context& context, const Json& node, const std::string& path);
RationalVector combination(const RationalMatrix& basis, const Triple& t);
std::string basis_words(const RationalMatrix& basis);

// proof.reduction = {transform U, reduced_basis R}, U integral with det U = +-1 and R = U B
// exactly, so that R spans the lattice of B and the enumeration may run on R; a vector with
// coefficients t in R has coefficients t U in B. A proof without the key enumerates B itself.
struct Reduction {
    RationalMatrix reduced;
    IntegerMatrix transform;
    Triple given(const Triple& t) const;
};
Reduction replay_reduction(Context& context, const Json& proof, const RationalMatrix& basis);

// Replays proof.bound_data and proof.coefficient_bound for the rows R (|a_i| <= floor(2
// ||r_j x r_k||_1 / |det R|), Cramer and Hoelder, as every candidate has ||v||_inf <= 2), then
// calls decide(t, index) for every triple of that box with all coordinates of t R at most 2 in
// size (rejecting at proof.candidates when one is not listed), and for every listed triple outside
// the box. Returns det R.
using CandidateDecision = std::function<void(const Triple& t, std::size_t index)>;
mpq_class replay_candidates(Context& context, const Json& proof, const RationalMatrix& rows, const CandidateDecision& decide);

}  // namespace superpack_checker
