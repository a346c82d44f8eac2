#include "superpack/problems/critical/critical_forms.hpp"

#include "critical_linear.hpp"

namespace superpack {

ChartForms chart_forms(const ChartBox<DInterval>& box, const DInterval& two_p) {
    ChartForms forms;
    ChartPoint offset;
    for (int k = 0; k < chart_dimension; ++k) {
        forms.center[k] = midpoint(box.x[k]);
        offset[k] = box.x[k] - forms.center[k];
    }
    const Basis<DInterval> basis_center = chart_basis(forms.center, box.face2, box.face3, two_p);
    const std::array<DInterval, 3> g_center = chart_equations(basis_center, box.configuration, two_p);
    for (int i = 0; i < 3; ++i) forms.equations[i].at_center = g_center[i];
    forms.determinant.at_center = determinant(basis_center);
    forms.basis = basis_center;
    forms.center_basis = basis_center;
    // Hansen's mean-value form: slope k over the box with x_l at the centre for l > k. For x in
    // the box, f(x) - f(m) is the sum over k of f(x_1..x_k, m_(k+1)..) - f(x_1..x_(k-1), m_k..),
    // each a slope over that box times (x_k - m_k); those slopes are enclosed over smaller boxes
    // than the whole one, so tighter (NOTES.md 12.10).
    for (int k = 0; k < chart_dimension; ++k) {
        std::array<Jet<DInterval>, chart_dimension> seeded;
        for (int l = 0; l < chart_dimension; ++l)
            seeded[l] = l == k ? variable(box.x[l]) : constant(l < k ? box.x[l] : forms.center[l]);
        const Basis<Jet<DInterval>> jets = chart_basis(seeded, box.face2, box.face3, two_p);
        forms.passes[k] = jets;
        const std::array<Jet<DInterval>, 3> g_jets = chart_equations(jets, box.configuration, two_p);
        forms.determinant.slope[k] = determinant(jets).derivative;
        for (int i = 0; i < 3; ++i) forms.equations[i].slope[k] = g_jets[i].derivative;
        for (int r = 0; r < 3; ++r)
            for (int j = 0; j < 3; ++j) forms.basis[r][j] = forms.basis[r][j] + jets[r][j].derivative * offset[k];
    }
    return forms;
}

LinearForm short_vector_form(const ChartForms& forms, const Coefficients& c, const DInterval& two_p) {
    LinearForm h;
    h.at_center = half_norm_power(combination(forms.center_basis, c), two_p) - DInterval(1.0);
    for (int k = 0; k < chart_dimension; ++k)
        h.slope[k] = half_norm_power(combination(forms.passes[k], c), two_p).derivative;
    return h;
}

DInterval enclose(const LinearForm& form, const ChartPoint& x, const ChartPoint& center) {
    DInterval sum = form.at_center;
    for (int k = 0; k < chart_dimension; ++k) sum = sum + form.slope[k] * (x[k] - center[k]);
    return sum;
}

LinearForm combine(const std::vector<double>& weights, const std::vector<LinearForm>& forms) {
    const DInterval like(0.0);
    LinearForm sum{like, {}};
    sum.slope.fill(like);
    for (std::size_t i = 0; i < forms.size(); ++i) {
        const DInterval weight = from_doubles(like, weights[i], weights[i]);
        sum.at_center = sum.at_center + weight * forms[i].at_center;
        for (int k = 0; k < chart_dimension; ++k) sum.slope[k] = sum.slope[k] + weight * forms[i].slope[k];
    }
    return sum;
}

LinearForm lagrangian(const ChartForms& forms) {
    Matrix3 normal{};
    Vector3 right{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < chart_dimension; ++k)
                normal[i][j] += mid_double(forms.equations[i].slope[k]) * mid_double(forms.equations[j].slope[k]);
        for (int k = 0; k < chart_dimension; ++k)
            right[i] += mid_double(forms.equations[i].slope[k]) * mid_double(forms.determinant.slope[k]);
    }
    const Vector3 lambda = solve3(normal, right);
    return combine({1, -lambda[0], -lambda[1], -lambda[2]},
                   {forms.determinant, forms.equations[0], forms.equations[1], forms.equations[2]});
}

}  // namespace superpack
