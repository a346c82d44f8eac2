// Certified root isolation over a whole search box: a bisection that accounts for every
// piece (proved root-free, proved to hold exactly one root, or undecided with a reason).
#pragma once
#include <string>
#include <vector>

#include "superpack/solve/krawczyk.hpp"
#include "superpack/solve/partition.hpp"

namespace superpack {

// One piece of a subdivided search box and what is proved about it.
template <class I>
struct RootLeaf {
    std::vector<I> piece;  // a piece of the partition of the search box
    RootStatus status;
    std::vector<I> root;   // for `unique`: the refined box holding the root
    std::string reason;
};

// Subdivision of `box` (partition.hpp): the returned pieces partition it, and every piece is
// `none` (a component of f excludes 0 there, or Krawczyk proved no zero), `unique`
// (Krawczyk proved exactly one zero in its interior) or `undecided` (narrower than
// `min_width`, or the budget of `max_pieces` ran out: such pieces are kept, never dropped).
template <class I, class F>
std::vector<RootLeaf<I>> isolate_roots(const F& f, const std::vector<I>& box, double min_width,
                                       std::size_t max_pieces, double target_width) {
    auto classify = [&](const std::vector<I>& piece) -> Classification<RootLeaf<I>> {
        for (const I& value : f(piece))
            if (!contains_zero(value)) return decided(RootLeaf<I>{piece, RootStatus::none, {}, "a component of f has one sign"});
        const KrawczykResult<I> proof = krawczyk_isolate(f, piece, target_width, 60);
        if (proof.status == RootStatus::none) return decided(RootLeaf<I>{piece, RootStatus::none, {}, proof.reason});
        if (proof.status == RootStatus::unique) {
            // Every root in the piece lies in proof.box, which holds exactly one root. A ball
            // backend rounds intersections outward, so proof.box may poke out of the piece:
            // the piece then holds that root only if proof.box lies inside it.
            bool inside = true, apart = false;
            for (std::size_t k = 0; k < piece.size(); ++k) {
                I meet = piece[k];
                inside = inside && contains(piece[k], proof.box[k]);
                apart = apart || !intersect(meet, piece[k], proof.box[k]);
            }
            if (inside) return decided(RootLeaf<I>{piece, RootStatus::unique, proof.box, proof.reason});
            if (apart)
                return decided(RootLeaf<I>{piece, RootStatus::none, {}, "the only root near the piece lies outside it"});
        }
        return not_decided<RootLeaf<I>>(proof.reason);
    };
    auto give_up = [](const std::vector<I>& piece, const std::string& reason) {
        return RootLeaf<I>{piece, RootStatus::undecided, {}, reason};
    };
    return partition(std::vector<std::vector<I>>{box}, classify, give_up, SubdivisionLimits{min_width, max_pieces});
}

}  // namespace superpack
