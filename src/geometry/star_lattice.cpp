// check_star_lattice (NOTES.md 13.2): the complete enumeration of lattice.cpp with the overlap
// test of star bodies in place of the norm criterion.
#include <algorithm>
#include <string>

#include "superpack/geometry/lattice.hpp"

namespace superpack {

template <class I>
LatticeCheck<I> check_star_lattice(const Basis<I>& basis, const Superball& body, const StarLatticeBudget& budget) {
    if (body.convex()) throw InputError("the star-body check is for p < 1/2 (for a convex body the norm criterion decides)");
    LatticeCheck<I> check;
    std::vector<std::vector<I>> translations;
    const bool complete = for_each_candidate<I>(basis, check, [&](const Coefficients& abc, const std::array<I, 3>& v) {
        translations.emplace_back(v.begin(), v.end());
        check.evaluated.push_back(LatticeVector<I>{abc, abc, v, gauge(body, translations.back())});
    });
    if (!complete) return check;
    // Most candidates are decided in a few boxes; a contact never is. So each candidate first gets
    // first_boxes, and those still undecided share what is left of total_boxes: a lattice with
    // many contacts costs total_boxes, not total_boxes per contact.
    StarOverlapOptions options;
    options.max_boxes = budget.first_boxes;
    std::vector<StarOverlap<I>> tests;
    long spent = 0;
    for (const auto& v : translations) {
        tests.push_back(star_overlap(body, v, options));
        spent += tests.back().boxes;
    }
    const long open = std::count_if(tests.begin(), tests.end(), [](const StarOverlap<I>& t) { return t.disjoint == Outcome::undecided; });
    if (open > 0 && (budget.total_boxes - spent) / open > budget.first_boxes) {
        options.max_boxes = (budget.total_boxes - spent) / open;
        for (std::size_t i = 0; i < tests.size(); ++i)
            if (tests[i].disjoint == Outcome::undecided) tests[i] = star_overlap(body, translations[i], options);
    }
    long overlapping = 0;
    for (std::size_t i = 0; i < tests.size(); ++i) {
        if (tests[i].disjoint == Outcome::refuted) {
            if (!check.witness) {
                check.witness = check.evaluated[i];
                check.witness_point = tests[i].witness;
            }
            ++overlapping;
        } else if (tests[i].disjoint == Outcome::undecided) {
            check.near_contacts.push_back(check.evaluated[i]);
        }
    }
    if (overlapping > 0) {
        check.verdict = Outcome::refuted;
        check.reason = std::to_string(overlapping) +
                       " lattice vector(s) v (up to sign) with K + v meeting K in interior points (certified witness point)";
    } else if (!check.near_contacts.empty()) {
        check.reason = std::to_string(check.near_contacts.size()) +
                       " vector(s) (up to sign) whose overlap test ended undecided within the budget of " +
                       std::to_string(budget.total_boxes) + " boxes (near contacts: boundaries that may touch)";
    } else {
        check.verdict = Outcome::proved;
        check.reason = "for every candidate v the interiors of K and K + v are certified disjoint (star-body overlap test)";
    }
    return check;
}

template LatticeCheck<DInterval> check_star_lattice(const Basis<DInterval>&, const Superball&, const StarLatticeBudget&);
template LatticeCheck<Ball> check_star_lattice(const Basis<Ball>&, const Superball&, const StarLatticeBudget&);

}  // namespace superpack
