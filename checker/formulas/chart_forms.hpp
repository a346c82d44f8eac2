// The chart of the critical-lattice claim (NOTES.md 12.2) and the first-order forms over one
// chart box (12.3), written again for the checker from the producer's formulas
// (include/superpack/problems/critical/critical_chart.hpp, src/problems/critical/critical_forms.cpp,
// critical_contraction.cpp, critical_linear.cpp), with the same expression trees in the same
// order, so that by inclusion isotonicity each enclosure here lies inside the producer's up to
// the last bits: every fact the producer proved about a box the checker proves again.
//
// x = (s, t, a2, c2, a3, c3); q = 2p. v1 = (1, s, s t), v2 and v3 on cube faces; the basis rows
// are b_i = 2 v_i / ||v_i||_q, and the configuration's three further vectors w_i give the
// equations g_i = sum_j |w_ij / 2|^q - 1 = 0.
//
// The centres and splits of boxes are at Boost's binary64 median, computed here with MPFR at 53
// bits: the checker must cut its boxes exactly where the producer did, since the tree's stored
// ends refer to them (the split coordinate is written in the tree).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "checker/formulas/chart_gradient.hpp"
#include "checker/formulas/equations.hpp"
#include "checker/formulas/triple.hpp"

namespace superpack_checker {

// Minkowski's two configurations: A3 (b1 - b2, b2 - b3, b3 - b1 on bd(2K)) and W (the sums).
enum class Configuration { a3, w };
const char* configuration_name(Configuration configuration);
// The value at `key` of `object`: "A3" or "W".
Configuration read_configuration(Context& context, const Json& object, const std::string& path);
// b1, b2, b3, then the three the equations are about.
std::array<Triple, 6> configuration_triples(Configuration configuration);

using ChartPoint = std::array<Real, chart_dimension>;
ChartPoint chart_zeros(mpfr_prec_t precision);

struct ChartBox {
    Configuration configuration = Configuration::a3;
    int face2 = 0, face3 = 0;  // face f: x_(f/2) = +1 for even f, -1 for odd f
    ChartPoint x;
};

// The exponents at p: q = 2p, 1/q, each with its y - 1.
struct ChartSetting {
    Exponent q, inverse;
    Real half, two;
};
ChartSetting chart_setting(const mpq_class& p, mpfr_prec_t precision);

// Naive interval evaluation over the box.
struct ChartValues {
    Matrix3 basis;
    std::array<Real, 3> equations;
    Real determinant;
};
ChartValues chart_values(const ChartBox& box, const ChartSetting& setting);

// c1 b1 + c2 b2 + c3 b3, adding or subtracting a row for c_k = +-1 (no product by 1).
std::array<Real, 3> combination(const Matrix3& b, const Triple& c);
// sum_j |v_j / 2|^q.
Real half_norm_power(const std::array<Real, 3>& v, const ChartSetting& setting);

// f(m) and the slopes df/dx_k over the box: f(x) in f(m) + sum_k slope_k (x_k - m_k) on it.
struct ChartForm {
    Real at_center;
    ChartPoint slope;
};

struct ChartForms {
    ChartPoint center;                    // the median of each coordinate
    std::array<ChartForm, 3> equations;  // g_0, g_1, g_2
    ChartForm determinant;
    ChartValues naive;                    // the plain enclosures over the box
    Matrix3 basis;                        // the naive basis intersected with its mean-value form
    Matrix3 center_basis;                 // the basis at the centre
};
ChartForms chart_forms(const ChartBox& box, const ChartSetting& setting);
// The form of h_c = sum_j |(c B)_j / 2|^q - 1 over the forms' box (Hansen's slopes, as the
// producer's): where h_c < 0 the lattice vector c B (c != 0) lies inside 2K.
ChartForm short_vector_form(const ChartBox& box, const ChartForms& forms, const Triple& c, const ChartSetting& setting);

// f(m) + sum_k slope_k (x_k - m_k), summed in the order of k, for a box x inside the forms' box.
Real enclose(const ChartForm& form, const ChartPoint& x, const ChartPoint& center);
// sum_i weight_i f_i, each weight a point (any values are sound).
ChartForm combine(const std::vector<double>& weights, const std::vector<ChartForm>& forms);
// det - sum lambda_i g_i with lambda by least squares on the midpoint slopes (a floating-point
// guess, as the producer's): equal to det wherever g = 0.
ChartForm lagrangian(const ChartForms& forms);
// F_i = sum_j C_ij g_j, C the floating-point inverse of the midpoint slopes of g on the pivot
// columns: zero wherever g = 0, whatever C is.
std::array<ChartForm, 3> preconditioned(const ChartForms& forms, const std::array<int, 3>& pivots);

// A box end as the chart's rules need it: a binary64 number, 0 or of size at least 2^-1000 (so
// that the median's halving is exact in binary64 as in MPFR).
bool binary64_box_end(mpfr_srcptr x);
// Boost's median of a binary64 interval: RN(lo/2 + hi/2), clamped into [lo, hi] (a point).
Real median(const Real& x);

}  // namespace superpack_checker
