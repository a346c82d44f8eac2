// One start box's bisection tree in a critical-lattice certificate (NOTES.md 12.8), replayed in
// the checker's arithmetic: the string is read in pre-order with an explicit stack of the boxes
// still to decide (never recursion), and every step is proved again on the box it is about.
//
//     node     := round* terminal
//     round    := 'C' pivots step* ';'          pivots: three of '0'..'5', or "---"
//     step     := form coord ('l' hex16 | 'h' hex16 | 'x')    form: '0'..'3', or '4' ddd
//     terminal := 'S' coord node node | 'E' | 'n' | 'r' | 'v' | 'd' | 'm' | 's' ddd | 'c' digits '.'
//
// A round computes the forms over its box (chart_forms.hpp) and proves each cut slab free of
// what a leaf would have to decide: the preconditioned F_0..F_2 ('0'..'2') exclude 0 on it, or
// the Lagrangian ('3') misses [V_lo, T] and [-T, -V_lo], or a short vector's h_c ('4' and the
// coefficients c_i + 2, c != 0: sum |(c B)_j / 2|^q - 1 by Hansen's form) is < 0 (c B in 2K).
// 'x' cuts the whole box ('E' follows). 'S' splits at the median of the coordinate that follows
// it ('0'..'5', the producer's choice: any coordinate is sound, since both halves are replayed).
// The first-order leaves (n: some g_i has one sign; r: an orbit vector is longer than b1 in the max norm; v: |det| < V_lo; d: |det| > T on
// the configuration, by the Lagrangian; m: outside the fundamental domain of the relabellings
// that keep b1, a2 > a3 where v2 and v3 share a face or, for A3, b1 . (b2 + b3 - b1) < 0) are
// proved on the box after the rounds; the lattice
// leaves (s: a short vector; c: the box maps into a closing region) on the box of the last round,
// with the basis over it.
#pragma once
#include <array>
#include <chrono>
#include <string>

#include "checker/claims/critical_region.hpp"

namespace superpack_checker {

// The leaves by reason, as the producer counts them (an 'E' after a cut of F_i has no
// configuration point, after a cut of the Lagrangian it is a determinant leaf).
enum class LeafReason { determinant, no_configuration, relabelled, short_vector, volume, closing_region, symmetric };
constexpr int leaf_reasons = 7;
const char* reason_name(LeafReason reason);

struct TreeCounts {
    long nodes = 0;  // boxes replayed
    long rounds = 0, cuts = 0;
    std::array<long, leaf_reasons> leaves{};
    // A replay of more than a few seconds reports the boxes replayed on stderr every 2 s from here.
    std::chrono::steady_clock::time_point reported = std::chrono::steady_clock::now();
};

struct TreeSetting {
    ChartSetting chart;
    const ClosingRegions* regions = nullptr;
    Real volume_lo, threshold;  // V_lo (the lower end of the stated V(K)) and T, points
};

// A start box of proof.boxes: {configuration, face2, face3, x}, its ends binary64 numbers (0 or
// at least 2^-1000 in size) inside the chart's domain (s, t in [0, 1], the faces' coordinates in
// [-1, 1]).
ChartBox read_chart_box(Context& context, const Json& node, const std::string& path);

// Rejects at `path` (e.g. "proof.trees[3]") with the character offset and the step that failed;
// a string outside the grammar is malformed there.
void replay_tree(Context& context, const std::string& tree, const ChartBox& start, const TreeSetting& setting,
                 const std::string& path, TreeCounts& counts);

}  // namespace superpack_checker
