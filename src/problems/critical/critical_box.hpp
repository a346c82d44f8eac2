// The decision for one box of `superpack critical` (NOTES.md 12.3): each test proves its reason
// for every point of the box, or the box is contracted (the part cut off proved free of what a
// leaf must decide) and split.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "superpack/problems/critical/critical.hpp"

namespace superpack {

struct BoxContext {
    DInterval two_p;
    DInterval volume;     // V(K)
    DInterval threshold;  // T (a point)
    DInterval margin_above, margin_below;  // 1 + 2^-40 and 1 - 2^-40: the leaves' margins on T and V(K)
    DInterval sigma_margin;                // -2^-40: a symmetric leaf needs b1 . (b2 + b3 - b1) below it
    DInterval admissible;                  // [0, 1e300]: the values of h_c kept by the short-vector cut
    std::vector<Coefficients> short_candidates;  // |c_i| <= 2, one per pair, not in a configuration
    const std::vector<ClosingRegion<DInterval>>* regions = nullptr;
    const std::vector<ChartImage>* images = nullptr;
    double min_width = 0;
};

BoxContext box_context(const Rational& p, const DInterval& volume, const DInterval& threshold,
                       const std::vector<ClosingRegion<DInterval>>& regions, const std::vector<ChartImage>& images,
                       double min_width);

// A leaf's reason, or nothing when `box` (the given box after the contractors) must be split.
struct BoxDecision {
    std::optional<BoxReason> reason;
    ChartBox<DInterval> box;
};
// With a trace, the box's rounds and its leaf letter are appended in the tree grammar of the
// critical-lattice certificate (NOTES.md 12.8); a box to split gets its rounds only (the
// caller appends 'S', the split coordinate's digit and its halves). A box to split carries its
// split coordinate in box.split.
BoxDecision decide_box(const ChartBox<DInterval>& box, const BoxContext& context, std::string* trace = nullptr);

// The coordinate split_box splits at: box.split, or the widest when it is -1.
int split_coordinate(const ChartBox<DInterval>& box);
// The two halves of the box at the binary64 median of split_coordinate(box), lower half first.
std::array<ChartBox<DInterval>, 2> split_box(const ChartBox<DInterval>& box);

}  // namespace superpack
