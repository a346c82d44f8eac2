#include "checker/formulas/chart_forms.hpp"

#include <algorithm>
#include <cmath>

namespace superpack_checker {

namespace {

template <class T>
using Rows = std::array<std::array<T, 3>, 3>;

Real constant_like(const Real& like, long n) { return integer(n, like.precision()); }
Gradient constant_like(const Gradient& like, long n) { return constant(integer(n, like.value.precision())); }

// critical_chart.hpp's templates, over Real (values) and Gradient (values and slopes).
template <class T>
std::array<T, 3> face_point(int face, const T& a, const T& c) {
    const int axis = face / 2;
    std::array<T, 3> v{a, a, a};
    v[axis] = constant_like(a, face % 2 == 0 ? 1 : -1);
    v[axis == 0 ? 1 : 0] = a;
    v[axis == 2 ? 1 : 2] = c;
    return v;
}

template <class T>
std::array<T, 3> boundary_point(const std::array<T, 3>& v, const ChartSetting& setting) {
    const T sum = chart_pow_abs(v[0], setting.q) + chart_pow_abs(v[1], setting.q) + chart_pow_abs(v[2], setting.q);
    const T norm = chart_pow_positive(sum, setting.inverse);
    return {setting.two * v[0] / norm, setting.two * v[1] / norm, setting.two * v[2] / norm};
}

template <class T>
Rows<T> chart_basis(const std::array<T, chart_dimension>& x, int face2, int face3, const ChartSetting& setting) {
    const T one = constant_like(x[0], 1);
    const std::array<T, 3> v1{one, x[0], x[0] * x[1]};
    return {boundary_point(v1, setting), boundary_point(face_point(face2, x[2], x[3]), setting),
            boundary_point(face_point(face3, x[4], x[5]), setting)};
}

template <class T>
std::array<T, 3> combination_of(const Rows<T>& b, const Triple& c) {
    std::array<T, 3> v{b[0][0], b[0][0], b[0][0]};
    for (int j = 0; j < 3; ++j) {
        T sum = constant_like(b[0][j], 0);
        for (int k = 0; k < 3; ++k) {
            if (c[k] == 1) sum = sum + b[k][j];
            else if (c[k] == -1) sum = sum - b[k][j];
            else if (c[k] != 0) sum = sum + constant_like(b[k][j], c[k]) * b[k][j];
        }
        v[j] = sum;
    }
    return v;
}

template <class T>
T half_norm_power_of(const std::array<T, 3>& v, const ChartSetting& setting) {
    return chart_pow_abs(v[0] * setting.half, setting.q) + chart_pow_abs(v[1] * setting.half, setting.q) +
           chart_pow_abs(v[2] * setting.half, setting.q);
}

template <class T>
std::array<T, 3> chart_equations(const Rows<T>& b, Configuration configuration, const ChartSetting& setting) {
    const std::array<Triple, 6> triples = configuration_triples(configuration);
    std::array<T, 3> g{b[0][0], b[0][0], b[0][0]};
    for (int i = 0; i < 3; ++i)
        g[i] = half_norm_power_of(combination_of(b, triples[3 + i]), setting) - constant_like(b[0][0], 1);
    return g;
}

template <class T>
T determinant_of(const Rows<T>& b) {
    return b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
           b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
}

// critical_linear.cpp: Cramer's rule in binary64, zero when m is nearly singular.
using Vector3d = std::array<double, 3>;
using Matrix3d = std::array<Vector3d, 3>;

double determinant3(const Matrix3d& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

Vector3d solve3(const Matrix3d& m, const Vector3d& r) {
    const double d = determinant3(m);
    double scale = 0;
    for (const Vector3d& row : m)
        for (double x : row) scale = std::max(scale, std::fabs(x));
    if (!(std::fabs(d) > 1e-12 * scale * scale * scale)) return {0, 0, 0};
    Vector3d y{};
    for (int i = 0; i < 3; ++i) {
        Matrix3d a = m;
        for (int k = 0; k < 3; ++k) a[k][i] = r[k];
        y[i] = determinant3(a) / d;
    }
    return y;
}

Real point(double x, mpfr_prec_t precision) {
    return doubles(x, x, precision);  // exact: precision >= 53
}

}  // namespace

const char* configuration_name(Configuration configuration) { return configuration == Configuration::a3 ? "A3" : "W"; }

Configuration read_configuration(Context& context, const Json& object, const std::string& path) {
    const std::string name = context.string_at(object, "configuration", path);
    if (name == "A3") return Configuration::a3;
    if (name == "W") return Configuration::w;
    context.malformed(path + ".configuration", "expected \"A3\" or \"W\"");
}

std::array<Triple, 6> configuration_triples(Configuration configuration) {
    if (configuration == Configuration::a3)
        return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, -1, 0}, {0, 1, -1}, {-1, 0, 1}}};
    return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}}};
}

ChartPoint chart_zeros(mpfr_prec_t precision) {
    const Real zero(precision);
    return {zero, zero, zero, zero, zero, zero};
}

ChartSetting chart_setting(const mpq_class& p, mpfr_prec_t precision) {
    const mpq_class q = 2 * p;
    return {exponent(q, precision), exponent(1 / q, precision), rational(mpq_class(1, 2), precision), integer(2, precision)};
}

ChartValues chart_values(const ChartBox& box, const ChartSetting& setting) {
    const Matrix3 basis = chart_basis(box.x, box.face2, box.face3, setting);
    return {basis, chart_equations(basis, box.configuration, setting), determinant_of(basis)};
}

std::array<Real, 3> combination(const Matrix3& b, const Triple& c) { return combination_of(b, c); }

Real half_norm_power(const std::array<Real, 3>& v, const ChartSetting& setting) { return half_norm_power_of(v, setting); }

// Pass k of Hansen's form: the basis with its x_k-slopes over the box whose coordinates after k
// are at the centre. Row r = k/2 is the only one that moves with x_k; the rows before it are the
// naive rows over the box, the rows after it the centre's, both constants.
namespace {
Rows<Gradient> hansen_rows(const ChartBox& box, const ChartForms& forms, int k, const ChartSetting& setting) {
    const int r = k / 2;
    auto constant_row = [&](int row) {
        const Matrix3& from = row < r ? forms.naive.basis : forms.center_basis;
        return std::array<Gradient, 3>{constant(from[row][0]), constant(from[row][1]), constant(from[row][2])};
    };
    Rows<Gradient> rows{constant_row(0), constant_row(1), constant_row(2)};
    const Gradient first = k % 2 == 0 ? variable(box.x[k], k) : constant(box.x[k - 1]);
    const Gradient second = k % 2 == 0 ? constant(forms.center[k + 1]) : variable(box.x[k], k);
    if (r == 0) {
        const Gradient one = constant(integer(1, box.x[0].precision()));
        rows[0] = boundary_point(std::array<Gradient, 3>{one, first, first * second}, setting);
    } else {
        rows[r] = boundary_point(face_point(r == 1 ? box.face2 : box.face3, first, second), setting);
    }
    return rows;
}
}  // namespace

ChartForm short_vector_form(const ChartBox& box, const ChartForms& forms, const Triple& c, const ChartSetting& setting) {
    const mpfr_prec_t precision = box.x[0].precision();
    ChartForm h{half_norm_power_of(combination_of(forms.center_basis, c), setting) - integer(1, precision),
                chart_zeros(precision)};
    for (int k = 0; k < chart_dimension; ++k)
        if (c[static_cast<std::size_t>(k / 2)] != 0)
            h.slope[k] = slope_at(half_norm_power_of(combination_of(hansen_rows(box, forms, k, setting), c), setting), k);
    return h;
}

ChartForms chart_forms(const ChartBox& box, const ChartSetting& setting) {
    const mpfr_prec_t precision = box.x[0].precision();
    ChartBox center_box = box;
    for (int k = 0; k < chart_dimension; ++k) center_box.x[k] = median(box.x[k]);
    const ChartValues at_center = chart_values(center_box, setting);
    const ChartValues naive = chart_values(box, setting);
    const ChartPoint zeros = chart_zeros(precision);
    ChartForms forms{center_box.x,
                     {ChartForm{at_center.equations[0], zeros}, ChartForm{at_center.equations[1], zeros},
                      ChartForm{at_center.equations[2], zeros}},
                     ChartForm{at_center.determinant, zeros},
                     naive,
                     at_center.basis,
                     at_center.basis};
    // Hansen's mean-value form, the producer's six Jet passes: slope k over the box with x_l at
    // the centre for l > k (f(x) - f(m) telescopes over the points (x_1..x_k, m_(k+1)..m_6), which
    // lie in that box). Row r of the basis depends on x_(2r) and x_(2r+1) only, so in pass k the
    // rows before r = k/2 are the naive rows over the box, the rows after it the centre's rows,
    // both constants, and an equation whose vector has no b_r has slope 0 there.
    const std::array<Triple, 6> triples = configuration_triples(box.configuration);
    for (int k = 0; k < chart_dimension; ++k) {
        const int r = k / 2;
        const Rows<Gradient> rows = hansen_rows(box, forms, k, setting);
        for (int i = 0; i < 3; ++i)
            if (triples[3 + i][r] != 0)
                forms.equations[i].slope[k] = slope_at(half_norm_power_of(combination_of(rows, triples[3 + i]), setting), k);
        forms.determinant.slope[k] = slope_at(determinant_of(rows), k);
        // The basis's mean-value form b(m) + sum_k db/dx_k (X_k - m_k) (only row r moves in x_k).
        const Real offset = box.x[k] - forms.center[k];
        for (int j = 0; j < 3; ++j)
            if (rows[r][j].slope[k]) forms.basis[r][j] = forms.basis[r][j] + *rows[r][j].slope[k] * offset;
    }
    // Then intersected with the naive enclosure (both hold the basis at every point of the box).
    for (int r = 0; r < 3; ++r)
        for (int j = 0; j < 3; ++j) {
            Real both(precision);
            if (intersect(both, forms.naive.basis[r][j], forms.basis[r][j])) forms.basis[r][j] = both;
            else forms.basis[r][j] = forms.naive.basis[r][j];
        }
    return forms;
}

Real enclose(const ChartForm& form, const ChartPoint& x, const ChartPoint& center) {
    Real sum = form.at_center;
    for (int k = 0; k < chart_dimension; ++k) sum = sum + form.slope[k] * (x[k] - center[k]);
    return sum;
}

ChartForm combine(const std::vector<double>& weights, const std::vector<ChartForm>& forms) {
    const mpfr_prec_t precision = forms[0].at_center.precision();
    ChartForm sum{Real(precision), chart_zeros(precision)};
    for (std::size_t i = 0; i < forms.size(); ++i) {
        const Real weight = point(weights[i], precision);
        sum.at_center = sum.at_center + weight * forms[i].at_center;
        for (int k = 0; k < chart_dimension; ++k) sum.slope[k] = sum.slope[k] + weight * forms[i].slope[k];
    }
    return sum;
}

ChartForm lagrangian(const ChartForms& forms) {
    Matrix3d normal{};
    Vector3d right{};
    std::array<std::array<double, chart_dimension>, 4> mid{};
    for (int k = 0; k < chart_dimension; ++k) {
        for (int i = 0; i < 3; ++i) mid[i][k] = middle(forms.equations[i].slope[k]);
        mid[3][k] = middle(forms.determinant.slope[k]);
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < chart_dimension; ++k) normal[i][j] += mid[i][k] * mid[j][k];
        for (int k = 0; k < chart_dimension; ++k) right[i] += mid[i][k] * mid[3][k];
    }
    const Vector3d lambda = solve3(normal, right);
    return combine({1, -lambda[0], -lambda[1], -lambda[2]},
                   {forms.determinant, forms.equations[0], forms.equations[1], forms.equations[2]});
}

std::array<ChartForm, 3> preconditioned(const ChartForms& forms, const std::array<int, 3>& pivots) {
    Matrix3d jacobian{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) jacobian[i][j] = middle(forms.equations[i].slope[pivots[j]]);
    Matrix3d inverse{};
    for (int j = 0; j < 3; ++j) {
        const Vector3d column = solve3(jacobian, {j == 0 ? 1.0 : 0.0, j == 1 ? 1.0 : 0.0, j == 2 ? 1.0 : 0.0});
        for (int i = 0; i < 3; ++i) inverse[i][j] = column[i];
    }
    const std::vector<ChartForm> equations(forms.equations.begin(), forms.equations.end());
    return {combine({inverse[0][0], inverse[0][1], inverse[0][2]}, equations),
            combine({inverse[1][0], inverse[1][1], inverse[1][2]}, equations),
            combine({inverse[2][0], inverse[2][1], inverse[2][2]}, equations)};
}

bool binary64_box_end(mpfr_srcptr x) {
    if (mpfr_zero_p(x)) return true;
    if (!mpfr_number_p(x)) return false;
    const double d = mpfr_get_d(x, MPFR_RNDN);
    return std::isfinite(d) && mpfr_cmp_d(x, d) == 0 && std::fabs(d) >= 0x1p-1000;
}

Real median(const Real& x) {
    mpfr_t half_lo, half_hi, m;
    mpfr_inits2(53, half_lo, half_hi, m, static_cast<mpfr_ptr>(nullptr));
    mpfr_div_2ui(half_lo, x.lo(), 1, MPFR_RNDN);  // exact: the ends are binary64 numbers
    mpfr_div_2ui(half_hi, x.hi(), 1, MPFR_RNDN);
    mpfr_add(m, half_lo, half_hi, MPFR_RNDN);
    if (mpfr_less_p(m, x.lo())) mpfr_set(m, x.lo(), MPFR_RNDN);
    if (mpfr_greater_p(m, x.hi())) mpfr_set(m, x.hi(), MPFR_RNDN);
    Real r = outward(m, m, x.precision());
    mpfr_clears(half_lo, half_hi, m, static_cast<mpfr_ptr>(nullptr));
    return r;
}

}  // namespace superpack_checker
