// Contractors of the branch and bound (NOTES.md 12.3): they shrink a box X to a box X' such that
// X \ X' holds no configuration point that a leaf would have to decide, so the part cut off is
// decided as a whole, without bisection, by the same facts the leaf reasons use.
#pragma once
#include <string>
#include <vector>

#include "superpack/problems/critical/critical_forms.hpp"

namespace superpack {

// Every point x of the box with f(x) in one of the target intervals stays: for each k whose slope
// is free of 0, f(x) = f(m) + sum_l slope_l (x_l - m_l) in Y gives
//     x_k in m_k + (Y - f(m) - sum_(l != k) slope_l (x_l - m_l)) / slope_k,
// each coordinate narrowed in turn (Gauss-Seidel: the narrowed ones are used at once, which is
// sound since the kept points lie in them). x must lie in the box the slopes are over (m need
// not lie in x: the segment from m to a point of x stays in that box). False: nothing is left.
//
// Each narrowed end is moved back out by 2^-20 of the coordinate's width (the margin), and a
// coordinate is found empty only when its allowed set misses it by that margin: so the slab cut
// off misses the targets by about |slope_k| times the margin, and the independent checker, whose
// enclosures differ from these in the last bits, proves the same cut (NOTES.md 12.8).
//
// With a trace, each cut is appended in the tree grammar of the critical-lattice certificate
// (12.8): form (one digit, or '4' and the short vector's three coefficient digits), coordinate,
// then 'l' or 'h' and the new end's 16 hex digits, or 'x' for empty.
bool contract_linear(const LinearForm& form, const std::vector<DInterval>& targets, ChartPoint& x, const ChartPoint& center,
                     const std::string& form_name = "3", std::string* trace = nullptr);

// The configuration's points (g_1 = g_2 = g_3 = 0) of the box: contract_linear on the three
// combinations C g, C the inverse of the midpoint Jacobian on three pivot columns (chosen by
// complete pivoting on slope x width), so that each combination depends mainly on one coordinate
// (the preconditioning of interval Gauss-Seidel). Any C is sound: C g = 0 wherever g = 0. The
// pivot coordinates are narrowed to the shadow of the manifold over the other three.
// With a trace: the three pivot columns (or "---" when the midpoint Jacobian has rank < 3), then
// the cuts of the combinations, named '0', '1', '2'.
bool contract_to_configuration(const ChartForms& forms, ChartPoint& x, std::string* trace = nullptr);

}  // namespace superpack
