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
#include <queue>
#include <string>
#include <vector>

#include "superpack/solve/bisection.hpp"

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

// bound(box, best) -> BoundedBox<I, Data> (bounded or not, with its reason), where best is the
// lowest certified value found so far (std::optional<I>), so that a bound can give up early
// where it already lies above it; value(point) ->
// std::optional<PointValue<I, Witness>>, f at a point of the domain (or nothing when it could
// not be certified there). `known`: a certified value of f at a point of the domain, if any.
template <class I, class Data, class Witness, class Bound, class Value>
Minimum<I, Data, Witness> minimise(const std::vector<I>& domain, const Bound& bound, const Value& value,
                                   std::optional<PointValue<I, Witness>> known, const MinimiseOptions& options) {
    using Box = BoundedBox<I, Data>;
    Minimum<I, Data, Witness> result;
    result.best = std::move(known);
    auto key = [](const Box& box) { return mid_double(lower_point(box.lower)); };
    auto later = [&](const Box& a, const Box& b) { return key(a) > key(b); };
    std::priority_queue<Box, std::vector<Box>, decltype(later)> open(later);
    auto consider = [&](const std::vector<I>& point) {
        std::optional<PointValue<I, Witness>> at = value(point);
        if (at && (!result.best || mid_double(upper_point(at->value)) < mid_double(upper_point(result.best->value))))
            result.best = std::move(at);
    };
    auto bound_below_best = [&](const std::vector<I>& box) {
        return bound(box, result.best ? std::optional<I>(result.best->value) : std::nullopt);
    };
    auto above_best = [&](const Box& box) {
        return result.best && certainly_less(upper_point(result.best->value), lower_point(box.lower));
    };
    // An unbounded box is bisected until its halves are bounded or it is too narrow.
    auto file = [&](Box box, auto& self) -> void {
        if (box.bounded) {
            open.push(std::move(box));
            return;
        }
        if (width_upper(box.box[widest_component(box.box)]) < options.min_undecided_width ||
            result.leaves.size() + open.size() + 2 > options.max_pieces) {
            box.fate = LeafFate::undecided;
            result.leaves.push_back(std::move(box));
            return;
        }
        auto halves = bisect_widest(box.box);
        self(bound_below_best(halves.first), self);
        self(bound_below_best(halves.second), self);
    };
    file(bound_below_best(domain), file);
    while (!open.empty()) {
        const Box& top = open.top();
        if (above_best(top)) break;  // so is everything still open
        if (result.best) {
            const double upper = mid_double(upper_point(result.best->value));
            if (upper - key(top) <= options.relative_tolerance * std::fabs(upper)) break;  // stopping rule only
        }
        if (result.leaves.size() + open.size() + 2 > options.max_pieces ||
            width_upper(top.box[widest_component(top.box)]) < options.min_width)
            break;
        const std::vector<I> box = top.box;
        open.pop();
        consider(center_of(box));
        auto halves = bisect_widest(box);
        file(bound_below_best(halves.first), file);
        file(bound_below_best(halves.second), file);
    }
    bool undecided = false;
    for (const Box& leaf : result.leaves) undecided = undecided || leaf.fate == LeafFate::undecided;
    if (result.best) result.lowest = result.best->value;
    while (!open.empty()) {
        Box leaf = open.top();
        open.pop();
        if (above_best(leaf)) {
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
