// Depth-first subdivision of a domain into decided pieces, on the branch-and-bound engine
// (branch_and_bound.hpp): each box is classified by the caller, and a box it cannot decide is
// bisected (bisection.hpp) until it is decided, too narrow, or the budget of pieces is spent. The leaves partition the domain: nothing is
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
#include "superpack/solve/branch_and_bound.hpp"

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

namespace partition_detail {

// partition's driver of the branch and bound (depth first, one thread): the caller's classify
// decides a box, and a box it cannot decide is bisected or given up on.
template <class I, class LeafType, class Classify, class GiveUp>
struct Driver {
    using Box = std::vector<I>;
    using Leaf = LeafType;
    static constexpr bool single_reason = true;
    const Classify& classify;
    const GiveUp& give_up;
    const SubdivisionLimits& limits;
    std::vector<Leaf> leaves;

    Examined<Box, Leaf> examine(const Box& box, Visit& visit) const {
        Classification<Leaf> result = classify(box);
        if (result.leaf) return leaf_of<Box>(std::move(*result.leaf));
        if (width_upper(box[widest_component(box)]) < limits.min_width ||
            static_cast<std::size_t>(visit.closed_leaves + visit.queued) + 2 > limits.max_pieces)
            return leaf_of<Box>(give_up(box, result.reason + "; subdivision budget reached"));
        return split_of<Box, Leaf>(box);
    }
    std::array<Box, 2> split(const Box& box) const {
        auto halves = bisect_widest(box);
        return {std::move(halves.first), std::move(halves.second)};
    }
    void collect(Leaf&& leaf) { leaves.push_back(std::move(leaf)); }
};

}  // namespace partition_detail

// classify(box) -> Classification<Leaf>; give_up(box, reason) -> Leaf, the undecided leaf of a
// box that is too narrow or over budget (its reason ends with "; subdivision budget reached").
// `pieces`, in order, are the first boxes (their union is the domain).
template <class I, class Classify, class GiveUp>
auto partition(const std::vector<std::vector<I>>& pieces, const Classify& classify, const GiveUp& give_up,
               const SubdivisionLimits& limits) {
    using Leaf = typename decltype(classify(pieces.front()).leaf)::value_type;
    partition_detail::Driver<I, Leaf, Classify, GiveUp> driver{classify, give_up, limits, {}};
    branch_and_bound(driver, pieces, BranchOptions{});
    return std::move(driver.leaves);
}

}  // namespace superpack
