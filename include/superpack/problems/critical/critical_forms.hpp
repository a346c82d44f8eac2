// First-order forms of one chart box (NOTES.md 12.3): for f one of g_1, g_2, g_3, det or a
// Lagrangian, an enclosure of f at the box's centre m and of each slope df/dx_k over the whole
// box X, so that f(x) lies in f(m) + sum_k slope_k (x_k - m_k) for every x in X (the mean value
// theorem on the segment from m to x, which lies in the convex X).
#pragma once
#include <array>
#include <vector>

#include "superpack/arith/jet.hpp"
#include "superpack/problems/critical/critical.hpp"

namespace superpack {

using ChartPoint = std::array<DInterval, chart_dimension>;

struct LinearForm {
    DInterval at_center;
    ChartPoint slope;
};

struct ChartForms {
    ChartPoint center;
    std::array<LinearForm, 3> equations;  // g_1, g_2, g_3
    LinearForm determinant;
    Basis<DInterval> basis;  // the basis's own mean-value enclosure over X
    Basis<DInterval> center_basis;
    std::array<Basis<Jet<DInterval>>, chart_dimension> passes;  // pass k: the basis and its x_k-slopes (Hansen's box)
};

ChartForms chart_forms(const ChartBox<DInterval>& box, const DInterval& two_p);

// f(m) + sum_k slope_k (x_k - m_k) over the box x (which must lie in the box the slopes are over).
DInterval enclose(const LinearForm& form, const ChartPoint& x, const ChartPoint& center);

// The form of h_c = sum_j |(c B)_j / 2|^(2p) - 1 (c B a lattice vector, c != 0): where h_c < 0,
// c B lies inside 2K and the lattice is not admissible (NOTES.md 12.3, the short-vector cut).
LinearForm short_vector_form(const ChartForms& forms, const Coefficients& c, const DInterval& two_p);

// sum_i weight_i f_i: the form of the combination (the weights are points, any values).
LinearForm combine(const std::vector<double>& weights, const std::vector<LinearForm>& forms);

// The Lagrangian det - sum lambda_i g_i, equal to det at every configuration point, with lambda by
// least squares on the midpoint gradients (a floating-point guess: any lambda is sound), so that
// its slope over the box is the slope of det along the configuration's manifold.
LinearForm lagrangian(const ChartForms& forms);

}  // namespace superpack
