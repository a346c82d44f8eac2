// Certified root isolation over a whole search box: a bisection that accounts for every
// piece (proved root-free, proved to hold exactly one root, or undecided with a reason).
#pragma once
#include <string>
#include <vector>

#include "superpack/solve/krawczyk.hpp"

namespace superpack {

// One piece of a subdivided search box and what is proved about it.
template <class I>
struct RootLeaf {
    std::vector<I> piece;  // a piece of the partition of the search box
    RootStatus status;
    std::vector<I> root;   // for `unique`: the refined box holding the root
    std::string reason;
};

// Branch and bound over `box`: the returned pieces partition it, and every piece is
// `none` (a component of f excludes 0 there, or Krawczyk proved no zero), `unique`
// (Krawczyk proved exactly one zero in its interior) or `undecided` (narrower than
// `min_width`, or the budget of `max_pieces` ran out: such pieces are kept, never dropped).
template <class I, class F>
std::vector<RootLeaf<I>> isolate_roots(const F& f, const std::vector<I>& box, double min_width,
                                       std::size_t max_pieces, double target_width) {
    std::vector<RootLeaf<I>> leaves;
    std::vector<std::vector<I>> pending{box};
    while (!pending.empty()) {
        std::vector<I> piece = pending.back();
        pending.pop_back();
        bool excluded = false;
        for (const I& value : f(piece)) excluded = excluded || !contains_zero(value);
        if (excluded) {
            leaves.push_back({piece, RootStatus::none, {}, "a component of f has one sign"});
            continue;
        }
        const KrawczykResult<I> proof = krawczyk_isolate(f, piece, target_width, 60);
        if (proof.status == RootStatus::none) {
            leaves.push_back({piece, RootStatus::none, {}, proof.reason});
            continue;
        }
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
            if (inside) {
                leaves.push_back({piece, RootStatus::unique, proof.box, proof.reason});
                continue;
            }
            if (apart) {
                leaves.push_back({piece, RootStatus::none, {}, "the only root near the piece lies outside it"});
                continue;
            }
        }
        std::size_t widest = 0;
        for (std::size_t k = 1; k < piece.size(); ++k)
            if (width_upper(piece[k]) > width_upper(piece[widest])) widest = k;
        if (width_upper(piece[widest]) < min_width || leaves.size() + pending.size() + 2 > max_pieces) {
            leaves.push_back({piece, RootStatus::undecided, {}, proof.reason + "; subdivision budget reached"});
            continue;
        }
        const I center = midpoint(piece[widest]);
        std::vector<I> left = piece, right = piece;
        left[widest] = hull(lower_point(piece[widest]), center);
        right[widest] = hull(center, upper_point(piece[widest]));
        pending.push_back(right);
        pending.push_back(left);
    }
    return leaves;
}

}  // namespace superpack
