#include "superpack/geometry/star_overlap.hpp"

#include <optional>
#include <string>

#include "superpack/geometry/star_cases.hpp"
#include "superpack/solve/bisection.hpp"
#include "superpack/solve/branch_and_bound.hpp"

namespace superpack {

namespace {

// g(x - c) = sum |x_i - c_i|^q over a box, by monotonicity in |x_i - c_i|.
template <class I>
I shifted_gauge_power(const std::vector<I>& x, const std::vector<I>& c, const I& q) {
    I sum = pow_abs(x[0] - c[0], q);
    for (std::size_t i = 1; i < x.size(); ++i) sum = sum + pow_abs(x[i] - c[i], q);
    return sum;
}

// Narrows the box x to what can hold points with g(x - c) < 1 for some c in the box c:
// |x_i - c_i|^q < 1 - sum_(j != i) |x_j - c_j|^q <= 1 - L_i, L_i a lower bound of that sum on the
// box, so |x_i - c_i| <= r_i = (1 - L_i)^(1/q) rounded up. Returns false when no such point is
// left (the box is discarded).
template <class I>
bool contract(std::vector<I>& x, const std::vector<I>& c, const I& q, const I& inverse_q) {
    const auto field = field_of(q);
    const I one = field.integer(1);
    std::vector<I> power;
    for (std::size_t i = 0; i < x.size(); ++i) power.push_back(pow_abs(x[i] - c[i], q));
    for (std::size_t i = 0; i < x.size(); ++i) {
        I rest = field.integer(0);
        for (std::size_t j = 0; j < x.size(); ++j)
            if (j != i) rest = rest + power[j];
        const I slack = upper_point(one - lower_point(rest));  // >= 1 - L_i
        if (!certainly_positive(slack)) return false;            // |x_i - c_i|^q < 0: nothing
        const I radius = upper_point(pow_nonneg(slack, inverse_q));
        const I reach = hull(lower_point(lower_point(c[i]) - radius), upper_point(upper_point(c[i]) + radius));
        if (!intersect(x[i], x[i], reach)) return false;
        power[i] = pow_abs(x[i] - c[i], q);
    }
    return !certainly_nonnegative(shifted_gauge_power(x, c, q) - one);
}

// The larger of two lower ends (point intervals), for the bound over the boxes left.
template <class I>
I larger_point(const I& a, const I& b) {
    return certainly_less(a, b) ? b : a;
}

template <class I>
I lower_bound_of_both(const std::vector<I>& x, const std::vector<I>& origin, const std::vector<I>& v, const I& q) {
    return larger_point(lower_point(shifted_gauge_power(x, origin, q)), lower_point(shifted_gauge_power(x, v, q)));
}

// star_overlap's driver of the branch and bound, best first: the box with the least lower
// bound of max(g, g(. - v)) next, as in a global minimisation of that function against the
// threshold 1. A depth-first order followed the boundary of one body for ever where the bodies
// do overlap. The order is only a heuristic: every answer comes from the certified tests.
template <class I>
struct OverlapDriver {
    using Box = std::vector<I>;
    enum class Kind { discarded, witness, left };  // a leaf's reason
    struct Leaf {
        Kind kind;
        Box box;
        std::optional<StarOverlapWitness<I>> witness;
    };
    const std::vector<I>& origin;
    const std::vector<I>& v;
    const I &q, &inverse_q, &one;
    const StarOverlapOptions& options;
    StarOverlap<I>& result;

    double priority(const Box& box) const { return mid_double(lower_bound_of_both(box, origin, v, q)); }

    Examined<Box, Leaf> examine(const Box& box, Visit&) const {
        std::vector<I> x = box;
        // Contract by both inequalities until a pass narrows the box by less than a tenth.
        bool empty = false;
        for (int pass = 0; pass < 8 && !empty; ++pass) {
            const double before = width_upper(x[widest_component(x)]);
            empty = !contract(x, origin, q, inverse_q) || !contract(x, v, q, inverse_q);
            if (!empty && width_upper(x[widest_component(x)]) > 0.9 * before) break;
        }
        if (empty) return leaf_of<Box>(Leaf{Kind::discarded, {}, std::nullopt});
        const std::vector<I> center = center_of(x);
        const I value = shifted_gauge_power(center, origin, q), translate = shifted_gauge_power(center, v, q);
        if (certainly_less(value, one) && certainly_less(translate, one))
            return leaf_of<Box>(Leaf{Kind::witness, {}, StarOverlapWitness<I>{center, value, translate}}, true);
        return split_of<Box, Leaf>(std::move(x));
    }
    std::array<Box, 2> split(const Box& box) const {
        auto halves = bisect_widest(box);
        return {std::move(halves.first), std::move(halves.second)};
    }
    Leaf unexamined(const Box& box) const { return Leaf{Kind::left, box, std::nullopt}; }
    std::size_t reason(const Leaf& leaf) const { return static_cast<std::size_t>(leaf.kind); }
    // The boxes left are handed over least first, so the listed ones are the nearest to a contact.
    void collect(Leaf&& leaf) {
        if (leaf.kind == Kind::witness) {
            result.disjoint = Outcome::refuted;
            result.witness = std::move(leaf.witness);
        }
        if (leaf.kind != Kind::left) return;
        ++result.remaining_count;
        const I bound = lower_bound_of_both(leaf.box, origin, v, q);
        if (!result.remaining_bound || certainly_less(bound, *result.remaining_bound)) result.remaining_bound = bound;
        if (static_cast<int>(result.remaining.size()) < options.max_remaining) result.remaining.push_back(std::move(leaf.box));
    }
};

}  // namespace

template <class I>
StarOverlap<I> star_overlap(const Superball& body, const std::vector<I>& v, const StarOverlapOptions& options) {
    if (static_cast<int>(v.size()) != body.dimension)
        throw InputError("star overlap: a translation of " + std::to_string(v.size()) + " coordinates for a body of dimension " +
                         std::to_string(body.dimension));
    const auto field = field_of(v[0]);
    const I q = field.rational(2 * body.p), inverse_q = field.rational(1 / (2 * body.p));
    const I one = field.integer(1), half = field.rational(Rational(1, 2));
    const std::vector<I> origin(v.size(), field.integer(0));
    StarOverlap<I> result;

    // The interiors lie in the open cubes (-1, 1)^d and v + (-1, 1)^d, disjoint when some
    // |v_i| >= 2. Decided here without a power, whose enclosure of 1^q is wider than 1: two tips
    // meeting on a coordinate axis, as K and K + 2 e_1 at x_1 = 1, are never separated by boxes
    // (and a ball backend cannot even hold the box x_1 in [1, 1] without a radius).
    for (const I& vi : v)
        if (certainly_nonnegative(abs(vi) - field.integer(2))) {
            result.disjoint = Outcome::proved;
            return result;
        }
    // For 2p <= 1 the closed form of NOTES.md 13.5 decides disjointness in d 2^(d-1) interval
    // tests, contacts included. An overlap it proves comes without a point, and an undecided case
    // may still be decided by boxes: both go on to the cover, which finds the witness.
    if (options.closed_form && 2 * body.p <= 1 && star_disjoint_by_cases(body, v) == Outcome::proved) {
        result.disjoint = Outcome::proved;
        return result;
    }
    // Both bodies lie in their cubes [-1, 1]^d and v + [-1, 1]^d.
    std::vector<I> start;
    for (const I& vi : v) {
        I both = vi;  // replaced by the intersection
        if (!intersect(both, hull(-one, one), hull(lower_point(lower_point(vi) - one), upper_point(upper_point(vi) + one)))) {
            result.disjoint = Outcome::proved;
            return result;
        }
        start.push_back(both);
    }
    // x -> v - x maps the set {g(x) < 1, g(x - v) < 1} onto itself (K = -K), so each of its points
    // or its image has x_k <= v_k / 2: keep that half of the widest coordinate.
    const std::size_t k = widest_component(start);
    if (!intersect(start[k], start[k], hull(lower_point(start[k]), upper_point(v[k] * half)))) {
        result.disjoint = Outcome::proved;
        return result;
    }

    OverlapDriver<I> driver{origin, v, q, inverse_q, one, options, result};
    BranchOptions search;
    search.order = BranchOrder::best_first;
    search.max_boxes = options.max_boxes;
    result.boxes = branch_and_bound(driver, {start}, search).examined;
    if (result.disjoint == Outcome::undecided && result.remaining_count == 0) result.disjoint = Outcome::proved;
    return result;
}

template StarOverlap<DInterval> star_overlap(const Superball&, const std::vector<DInterval>&, const StarOverlapOptions&);
template StarOverlap<Ball> star_overlap(const Superball&, const std::vector<Ball>&, const StarOverlapOptions&);

}  // namespace superpack
