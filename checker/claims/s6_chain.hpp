// The chain of an S6 audit (NOTES.md 4.2, 8.4): from the point proof at p = 9/10 (proof.anchor)
// up and down through the pieces. Each piece's box must hold exactly one KKT point of the six
// triples for every p of the piece, replayed with the mean-value form in p (ParameterForm,
// replay.hpp) from the stored midpoint p0; at the end it shares with the piece before it
// (towards 9/10) the root of its box, by Krawczyk at that exact p, must lie in the box before,
// where the root is unique: so both boxes hold the one branch. A piece without a box, or whose
// link fails, breaks the chain on its side of 9/10.
#pragma once
#include <optional>
#include <vector>

#include "checker/core/replay.hpp"

namespace superpack_checker {

struct PieceEnds {
    mpq_class lo, hi;
};

// The anchor's p.
mpq_class s6_anchor_p();

// Per piece: the checker's root box over the piece if the piece is on the unbroken chain, else
// nothing. Rejects at proof.anchor..., proof.pieces[k].parameters... or claim.data.pieces.
std::vector<std::optional<Box>> replay_s6_chain(Context& context, const std::vector<PieceEnds>& pieces, const Json& proofs,
                                                const Json& anchor);

}  // namespace superpack_checker
