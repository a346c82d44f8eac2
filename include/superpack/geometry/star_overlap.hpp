// Do the interiors of the superball K = {g(x) <= 1}, g(x) = sum |x_i|^(2p), and its translate
// K + v meet? For p < 1/2 K is a star body: its gauge is not a norm, K - K is larger than 2K,
// and "every lattice vector has gauge >= 2" is no packing test (v = (9/10, 9/10, 0) at p = 3/10
// has gauge 2.86, yet K + v meets K at (9/10, 0, 0), where one body's x-arm crosses the other's
// y-arm). So this test decides the question itself, for any p > 0 and a v known as a box of
// numbers (each answer holds for every v in it):
//
//   - disjoint (proved): for 2p <= 1 first by the closed form of geometry/star_cases.hpp, which
//     decides contacts too; otherwise, or when that is undecided, a branch and bound over x
//     covers the region where both bodies can have points, [-1, 1]^d and v + [-1, 1]^d, and
//     discards every box on which g certainly is >= 1 or g(. - v) certainly is >= 1, after
//     contracting it by the two inequalities;
//   - overlapping (refuted): a point x with g(x) < 1 and g(x - v) < 1, both certified (the
//     witness, with the two values);
//   - undecided: the box budget ran out, typically at a contact (boundaries that touch, where no
//     box around the contact point can be discarded); the boxes left are listed with the least
//     certified lower bound of max(g(x), g(x - v)) over them.
//
// |t|^(2p) is not Lipschitz at 0 for 2p < 1, so every enclosure goes by monotonicity in |t|
// (pow_abs: [0, max|t|^(2p)] on a box around 0), never through a derivative.
#pragma once
#include <optional>
#include <vector>

#include "superpack/arith/outcome.hpp"
#include "superpack/geometry/body.hpp"

namespace superpack {

struct StarOverlapOptions {
    long max_boxes = 200000;  // the budget of boxes decided before the answer is undecided
    int max_remaining = 16;   // of the boxes left at an undecided answer, how many are listed
    // For 2p <= 1, decide by the closed form (geometry/star_cases.hpp) before any box; false tests
    // the box cover alone.
    bool closed_form = true;
};

template <class I>
struct StarOverlapWitness {
    std::vector<I> point;   // x (point intervals)
    I value, value_at_translate;  // g(x) < 1 and g(x - v) < 1, certified
};

template <class I>
struct StarOverlap {
    // proved: the interiors of K and K + v are disjoint (for every v in the box);
    // refuted: they meet (witness); undecided: see remaining.
    Outcome disjoint = Outcome::undecided;
    std::optional<StarOverlapWitness<I>> witness;
    long boxes = 0;  // boxes decided (discarded, split or holding the witness)
    std::vector<std::vector<I>> remaining;  // at most max_remaining of the boxes left
    long remaining_count = 0;
    std::optional<I> remaining_bound;  // holds min over the boxes left of a lower bound of max(g, g(. - v))
};

// K of dimension v.size() (2 or 3, the body's); p > 0. Throws InputError for another size.
template <class I>
StarOverlap<I> star_overlap(const Superball& body, const std::vector<I>& v, const StarOverlapOptions& options = {});

}  // namespace superpack
