// What the two critical-lattice claim kinds share (claim_critical_lattice.cpp, one file of trees;
// claim_critical_cover.cpp, a cover of such files): the bound's numbers T and V(K) in claim.data,
// the chart domain of NOTES.md 12.2 split K times, and the words of the theorem.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "checker/formulas/chart_forms.hpp"

namespace superpack_checker {

// claim.data.threshold: T, a positive point with V_lo <= T; claim.data.volume: V(K), an enclosure
// holding the checker's own (so V_lo, its lower end, is a lower bound of V(K)).
struct CriticalBound {
    Real threshold, own_volume, volume, volume_lo;
};
CriticalBound read_critical_bound(Context& context, const Json& data, const mpq_class& p);
// claim.data.upper_phi must hold V(K) / T; the enclosure stated.
Real read_upper_phi(Context& context, const Json& data, const CriticalBound& bound);

// A start box with binary64 ends, compared exactly.
struct DomainBox {
    Configuration configuration = Configuration::a3;
    int face2 = 0, face3 = 0;
    std::array<double, 2 * chart_dimension> ends{};  // lo, hi of each coordinate
    bool operator<(const DomainBox& other) const;
    bool operator==(const DomainBox& other) const;
};
DomainBox domain_box(const ChartBox& box);  // the ends are binary64 numbers (read_chart_box)
std::string domain_box_text(const DomainBox& box);

// The whole chart domain's start boxes in the producer's order (superpack's split_domain): A3
// then W, face2 <= face3, the (s, t) square in four (the 168 top-level boxes), each then bisected
// `split` times at the midpoint of its widest coordinate (the first on ties), lower half first.
// Every end is a dyadic number of a few bits, so double arithmetic is exact here.
constexpr int max_domain_split = 8;
std::vector<DomainBox> chart_domain(int split);
// The two halves of a box by that rule, lower first.
std::array<DomainBox, 2> halves(const DomainBox& box);
// A cover's start box may be a piece of a box of the split domain, halved by the same rule at most
// this many times more (the branch and bound stops at widths of 1e-10, about 200 halvings).
constexpr int max_cover_depth = 64;

// The theorem's words on the whole domain, cut into `start_boxes` pieces, each bisected at least
// `split` times: where, and its consequence for every lattice packing.
std::string whole_domain_words(int split, std::size_t start_boxes);
extern const char* const whole_domain_consequence;

}  // namespace superpack_checker
