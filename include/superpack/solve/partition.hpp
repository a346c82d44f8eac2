// Depth-first subdivision of a domain into decided pieces: each box is classified by the
// caller, and a box it cannot decide is bisected (bisection.hpp) until it is decided, too
// narrow, or the budget of pieces is spent. The leaves partition the domain: nothing is
// dropped, and a piece given up on is returned as an undecided leaf with its reason.
// Leaves come out depth first, left half before right, so in one dimension from left to
// right: a caller may carry what a piece proved at its right end into the next piece.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "superpack/solve/bisection.hpp"

namespace superpack {

// What the caller decided about one box: a leaf, or why it could not decide (then the box is
// bisected, or given up on with that reason).
template <class Leaf>
struct Classification {
    std::optional<Leaf> leaf;
    std::string reason;
};
template <class Leaf>
Classification<Leaf> decided(Leaf leaf) {
    return {std::move(leaf), ""};
}
template <class Leaf>
Classification<Leaf> not_decided(std::string reason) {
    return {std::nullopt, std::move(reason)};
}

struct SubdivisionLimits {
    double min_width = 0;          // a box whose widest component is narrower is not bisected
    std::size_t max_pieces = 1;    // leaves plus pending boxes never exceed this
};

// classify(box) -> Classification<Leaf>; give_up(box, reason) -> Leaf, the undecided leaf of a
// box that is too narrow or over budget (its reason ends with "; subdivision budget reached").
// `pieces`, in order, are the first boxes (their union is the domain).
template <class I, class Classify, class GiveUp>
auto partition(const std::vector<std::vector<I>>& pieces, const Classify& classify, const GiveUp& give_up,
               const SubdivisionLimits& limits) {
    using Leaf = typename decltype(classify(pieces.front()).leaf)::value_type;
    std::vector<Leaf> leaves;
    std::vector<std::vector<I>> pending(pieces.rbegin(), pieces.rend());
    while (!pending.empty()) {
        const std::vector<I> box = pending.back();
        pending.pop_back();
        Classification<Leaf> result = classify(box);
        if (result.leaf) {
            leaves.push_back(std::move(*result.leaf));
            continue;
        }
        if (width_upper(box[widest_component(box)]) < limits.min_width ||
            leaves.size() + pending.size() + 2 > limits.max_pieces) {
            leaves.push_back(give_up(box, result.reason + "; subdivision budget reached"));
            continue;
        }
        auto halves = bisect_widest(box);
        pending.push_back(std::move(halves.second));
        pending.push_back(std::move(halves.first));
    }
    return leaves;
}

}  // namespace superpack
