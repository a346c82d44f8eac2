// Best-first branch and bound for min f over a box in R^n, with certified bounds: the caller
// encloses f over a box from below (bound) and evaluates f at points (value). The box with the
// lowest lower bound is bisected next (bisection.hpp) and f is evaluated at its center; once a
// box's lower bound lies above the best value found, it cannot hold a minimiser and is
// discarded. The leaves partition the domain: every leaf is discarded (proved to hold no
// minimiser), a candidate (its lower bound enters the certified minimum), or undecided
// (no bound; the minimum is then not certified).
//
// Soundness does not depend on the order of the search, the stopping rule or the choice of
// points: min f lies in [min over candidates of their lower bound, best value], because every
// box that may hold a minimiser is a candidate or undecided, and the best value is f at a
// point of the domain.
#pragma once
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "superpack/solve/bisection.hpp"
#include "superpack/solve/branch_and_bound.hpp"

namespace superpack {

enum class LeafFate { candidate, discarded, undecided };

inline const char* to_string(LeafFate fate) {
    switch (fate) {
        case LeafFate::candidate: return "candidate";
        case LeafFate::discarded: return "discarded";
        case LeafFate::undecided: return "undecided";
    }
    return "undecided";
}

// What bound(box) proved: for a bounded box, the lower end of `lower` is <= f on the whole box.
// `data` is whatever the caller keeps per box (the proof behind the bound).
template <class I, class Data>
struct BoundedBox {
    std::vector<I> box;
    bool bounded = false;
    I lower;
    Data data;
    std::string reason;
    LeafFate fate = LeafFate::undecided;  // set by minimise
};

// f at one point, certified, with what the caller keeps to show it (e.g. the lattice there).
template <class I, class Witness>
struct PointValue {
    I value;
    Witness witness;
};

struct MinimiseOptions {
    double relative_tolerance = 1e-9;  // stop when best - lowest lower bound <= this * |best| (a guess)
    std::size_t max_pieces = 1000;     // leaves plus open boxes
    double min_width = 1e-14;          // a candidate narrower than this is not bisected
    double min_undecided_width = 1e-12;  // an unbounded box is bisected down to this width
};

template <class I, class Data, class Witness>
struct Minimum {
    std::vector<BoundedBox<I, Data>> leaves;  // a partition of the domain, in the order closed
    std::optional<PointValue<I, Witness>> best;  // the lowest certified value found
    std::optional<I> lowest;                  // hull of the candidates' lower bounds and the best value
    bool certified = false;                   // no undecided leaf, and a best value exists
};

namespace minimise_detail {

// minimise's driver of the branch and bound. A new box (a child of a split, or the domain) is
// bounded at once and deferred into best-first order when bounded; one that is not is bisected
// at once, depth first, until its halves are bounded or it is too narrow. A deferred box taken
// back (the least lower bound) either ends the search (the stopping rule, the budget) or has f
// evaluated at its center and is bisected.
template <class I, class Data, class Witness, class Bound, class Value>
struct Driver {
    struct Box {
        std::vector<I> box;
        std::optional<BoundedBox<I, Data>> bounded;  // once bounded and deferred
    };
    struct Leaf {
        BoundedBox<I, Data> bounded;
        bool left = false;  // left open when the search stopped (classified after it)
    };
    const Bound& bound;
    const Value& value;
    const MinimiseOptions& options;
    Minimum<I, Data, Witness>& result;
    std::vector<BoundedBox<I, Data>> left;

    static double key(const BoundedBox<I, Data>& box) { return mid_double(lower_point(box.lower)); }
    bool above_best(const BoundedBox<I, Data>& box) const {
        return result.best && certainly_less(upper_point(result.best->value), lower_point(box.lower));
    }
    void consider(const std::vector<I>& point) {
        std::optional<PointValue<I, Witness>> at = value(point);
        if (at && (!result.best || mid_double(upper_point(at->value)) < mid_double(upper_point(result.best->value))))
            result.best = std::move(at);
    }

    Examined<Box, Leaf> examine(const Box& box, Visit& visit) {
        if (!box.bounded) {
            BoundedBox<I, Data> bounded = bound(box.box, result.best ? std::optional<I>(result.best->value) : std::nullopt);
            if (bounded.bounded) {
                const double priority = key(bounded);
                return defer_of<Box, Leaf>(Box{bounded.box, std::move(bounded)}, priority);
            }
            if (width_upper(bounded.box[widest_component(bounded.box)]) < options.min_undecided_width ||
                static_cast<std::size_t>(visit.closed_leaves + visit.deferred) + 2 > options.max_pieces) {
                bounded.fate = LeafFate::undecided;
                return leaf_of<Box>(Leaf{std::move(bounded), false});
            }
            return split_of<Box, Leaf>(Box{bounded.box, std::nullopt});
        }
        const BoundedBox<I, Data>& top = *box.bounded;
        if (above_best(top)) return stop_at<Box, Leaf>(box);  // so is everything still open
        if (result.best) {
            const double upper = mid_double(upper_point(result.best->value));
            if (upper - key(top) <= options.relative_tolerance * std::fabs(upper)) return stop_at<Box, Leaf>(box);  // stopping rule only
        }
        // The box taken back still counts as open here, as it did before it was taken.
        if (static_cast<std::size_t>(visit.closed_leaves + visit.deferred) + 1 + 2 > options.max_pieces ||
            width_upper(top.box[widest_component(top.box)]) < options.min_width)
            return stop_at<Box, Leaf>(box);
        consider(center_of(top.box));
        return split_of<Box, Leaf>(box);
    }
    std::array<Box, 2> split(const Box& box) const {
        auto halves = bisect_widest(box.box);
        return {Box{std::move(halves.first), std::nullopt}, Box{std::move(halves.second), std::nullopt}};
    }
    // Only boxes taken back from best-first order are left open (a new box is examined at once).
    Leaf unexamined(const Box& box) const { return Leaf{*box.bounded, true}; }
    std::size_t reason(const Leaf& leaf) const { return leaf.left ? 1 : 0; }
    void collect(Leaf&& leaf) {
        if (leaf.left)
            left.push_back(std::move(leaf.bounded));
        else
            result.leaves.push_back(std::move(leaf.bounded));
    }
};

}  // namespace minimise_detail

// bound(box, best) -> BoundedBox<I, Data> (bounded or not, with its reason), where best is the
// lowest certified value found so far (std::optional<I>), so that a bound can give up early
// where it already lies above it; value(point) ->
// std::optional<PointValue<I, Witness>>, f at a point of the domain (or nothing when it could
// not be certified there). `known`: a certified value of f at a point of the domain, if any.
// The search runs on the branch-and-bound engine (branch_and_bound.hpp), in one thread.
template <class I, class Data, class Witness, class Bound, class Value>
Minimum<I, Data, Witness> minimise(const std::vector<I>& domain, const Bound& bound, const Value& value,
                                   std::optional<PointValue<I, Witness>> known, const MinimiseOptions& options) {
    Minimum<I, Data, Witness> result;
    result.best = std::move(known);
    minimise_detail::Driver<I, Data, Witness, Bound, Value> driver{bound, value, options, result, {}};
    branch_and_bound(driver, {{domain, std::nullopt}}, BranchOptions{});
    bool undecided = false;
    for (const auto& leaf : result.leaves) undecided = undecided || leaf.fate == LeafFate::undecided;
    if (result.best) result.lowest = result.best->value;
    // The boxes left open, least first: those above the best value hold no minimiser.
    for (BoundedBox<I, Data>& leaf : driver.left) {
        if (driver.above_best(leaf)) {
            leaf.fate = LeafFate::discarded;
        } else {
            leaf.fate = LeafFate::candidate;
            result.lowest = result.lowest ? hull(*result.lowest, lower_point(leaf.lower)) : lower_point(leaf.lower);
        }
        result.leaves.push_back(std::move(leaf));
    }
    if (result.lowest && result.best) result.lowest = hull(lower_point(*result.lowest), upper_point(result.best->value));
    result.certified = !undecided && result.best.has_value();
    return result;
}

}  // namespace superpack
