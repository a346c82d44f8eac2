#include "critical_box.hpp"

#include <algorithm>
#include <cmath>

namespace superpack {

namespace {

using I = DInterval;

// The configuration vectors whose max norm may not exceed b1's (12.2): all five others for
// A3 (its relabellings act transitively on the six pairs), b2 and b3 for W (the relabellings
// of W keep {b1, b2, b3}).
std::vector<Coefficients> max_norm_orbit(MinkowskiCase configuration) {
    const std::array<Coefficients, 6> triples = configuration_triples(configuration);
    if (configuration == MinkowskiCase::a3) return {triples.begin() + 1, triples.end()};
    return {triples[1], triples[2]};
}

// Some coordinate of v certainly larger in size than `bound` (an upper end).
bool certainly_longer(const std::array<I, 3>& v, const I& bound) {
    for (const I& x : v)
        if (certainly_less(upper_point(bound), abs(x))) return true;
    return false;
}

// Cramer's rule for the 3x3 system m y = r; nothing when m is nearly singular. Floating point:
// the multipliers of the Lagrangian bound are guesses, any value is sound.
std::array<double, 3> solve3(const std::array<std::array<double, 3>, 3>& m, const std::array<double, 3>& r) {
    auto det3 = [](const std::array<std::array<double, 3>, 3>& a) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double d = det3(m);
    double scale = 0;
    for (const auto& row : m)
        for (double x : row) scale = std::max(scale, std::fabs(x));
    if (!(std::fabs(d) > 1e-12 * scale * scale * scale)) return {0, 0, 0};
    std::array<double, 3> y{};
    for (int i = 0; i < 3; ++i) {
        auto a = m;
        for (int k = 0; k < 3; ++k) a[k][i] = r[k];
        y[i] = det3(a) / d;
    }
    return y;
}

// The closing region test: some image's W^-1 B P^-1 lies inside its region.
bool in_closing_region(const Basis<I>& basis, const BoxContext& context) {
    for (const ChartImage& image : *context.images) {
        double distance = 0;
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) distance = std::max(distance, std::fabs(mid_double(basis[k][j]) - image.chart_basis[k][j]));
        const ClosingRegion<I>& region = (*context.regions)[image.region];
        if (distance > 8 * region.radius) continue;
        // Rows: W^-1 B; columns: u_(perm_j) = sign_j b_j.
        Basis<I> unmapped;
        for (int k = 0; k < 3; ++k) {
            const std::array<I, 3> row = combination(basis, image.inverse[k]);
            for (int j = 0; j < 3; ++j) unmapped[k][image.perm[j]] = image.sign[j] > 0 ? row[j] : -row[j];
        }
        if (region_contains(region, unmapped)) return true;
    }
    return false;
}

}  // namespace

BoxContext box_context(const Rational& p, const DInterval& volume, const DInterval& threshold,
                       const std::vector<ClosingRegion<DInterval>>& regions, const std::vector<ChartImage>& images,
                       double min_width) {
    const DoubleField field;
    BoxContext context;
    context.two_p = field.integer(2) * field.rational(p);
    context.volume = volume;
    context.threshold = threshold;
    context.regions = &regions;
    context.images = &images;
    context.min_width = min_width;
    for (long a = -2; a <= 2; ++a)
        for (long b = -2; b <= 2; ++b)
            for (long c = -2; c <= 2; ++c) {
                const Coefficients triple{a, b, c};
                if (triple == Coefficients{0, 0, 0} || representative(triple) != triple) continue;
                context.short_candidates.push_back(triple);
            }
    return context;
}

std::optional<BoxReason> classify_box(const ChartBox<I>& box, const BoxContext& context) {
    const DoubleField field;
    const I& two_p = context.two_p;
    const I one = field.integer(1);
    const std::array<Coefficients, 6> triples = configuration_triples(box.configuration);
    try {
        // Naive enclosures over the box.
        Basis<I> basis = chart_basis(box.x, box.face2, box.face3, two_p);
        std::array<I, 3> g = chart_equations(basis, box.configuration, two_p);
        for (const I& value : g)
            if (!contains_zero(value)) return BoxReason::no_configuration;
        for (const Coefficients& c : max_norm_orbit(box.configuration))
            if (certainly_longer(combination(basis, c), basis[0][0])) return BoxReason::relabelled;
        if (certainly_less(abs(determinant(basis)), context.volume)) return BoxReason::volume;

        // Mean-value forms: f(X) in f(m) + sum_k df/dx_k(X) (X_k - m_k), the derivatives by Jets.
        std::array<I, chart_dimension> center, offset;
        for (int k = 0; k < chart_dimension; ++k) {
            center[k] = midpoint(box.x[k]);
            offset[k] = box.x[k] - center[k];
        }
        const Basis<I> basis_center = chart_basis(center, box.face2, box.face3, two_p);
        const std::array<I, 3> g_center = chart_equations(basis_center, box.configuration, two_p);
        const I det_center = determinant(basis_center);
        std::array<I, chart_dimension> det_slope;
        std::array<std::array<I, chart_dimension>, 3> g_slope;
        Basis<I> basis_mean = basis_center;
        for (int k = 0; k < chart_dimension; ++k) {
            std::array<Jet<I>, chart_dimension> seeded;
            for (int l = 0; l < chart_dimension; ++l) seeded[l] = l == k ? variable(box.x[l]) : constant(box.x[l]);
            const Basis<Jet<I>> jets = chart_basis(seeded, box.face2, box.face3, two_p);
            const std::array<Jet<I>, 3> g_jets = chart_equations(jets, box.configuration, two_p);
            det_slope[k] = determinant(jets).derivative;
            for (int i = 0; i < 3; ++i) g_slope[i][k] = g_jets[i].derivative;
            for (int r = 0; r < 3; ++r)
                for (int j = 0; j < 3; ++j) basis_mean[r][j] = basis_mean[r][j] + jets[r][j].derivative * offset[k];
        }
        for (int i = 0; i < 3; ++i) {
            I mean = g_center[i];
            for (int k = 0; k < chart_dimension; ++k) mean = mean + g_slope[i][k] * offset[k];
            if (!contains_zero(mean)) return BoxReason::no_configuration;
        }
        for (int r = 0; r < 3; ++r)
            for (int j = 0; j < 3; ++j) intersect(basis[r][j], basis[r][j], basis_mean[r][j]);

        // The Lagrangian det - sum lambda_i g_i equals det at every configuration point; lambda
        // by least squares on the midpoint gradients, so that its slope over the box is the
        // slope of det along the configuration's manifold.
        std::array<std::array<double, 3>, 3> normal{};
        std::array<double, 3> right{};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < chart_dimension; ++k) normal[i][j] += mid_double(g_slope[i][k]) * mid_double(g_slope[j][k]);
            for (int k = 0; k < chart_dimension; ++k) right[i] += mid_double(g_slope[i][k]) * mid_double(det_slope[k]);
        }
        const std::array<double, 3> lambda = solve3(normal, right);
        I lagrangian = det_center;
        for (int i = 0; i < 3; ++i) lagrangian = lagrangian - from_doubles(one, lambda[i], lambda[i]) * g_center[i];
        for (int k = 0; k < chart_dimension; ++k) {
            I slope = det_slope[k];
            for (int i = 0; i < 3; ++i) slope = slope - from_doubles(one, lambda[i], lambda[i]) * g_slope[i][k];
            lagrangian = lagrangian + slope * offset[k];
        }
        if (certainly_less(context.threshold, lagrangian) || certainly_less(lagrangian, -context.threshold))
            return BoxReason::determinant;
        if (certainly_less(abs(lagrangian), context.volume)) return BoxReason::volume;

        if (in_closing_region(basis, context)) return BoxReason::closing_region;

        for (const Coefficients& c : context.short_candidates) {
            // The configuration's own vectors have norm 2 on M (and below 2 only off M, where g excludes).
            if (std::any_of(triples.begin(), triples.end(), [&](const Coefficients& t) { return representative(t) == c; }))
                continue;
            const std::array<I, 3> v = combination(basis, c);
            if (certainly_longer(v, field.integer(2))) continue;
            if (certainly_less(half_norm_power(v, two_p), one)) return BoxReason::short_vector;
        }
    } catch (const std::domain_error&) {
        // A power's contract refused an enclosure (it cannot on this chart, where every base of
        // a fractional power is a coordinate or a sum in [1, 3]): split, and at the floor undecided.
        double widest = 0;
        for (const I& x : box.x) widest = std::max(widest, width_upper(x));
        if (widest < context.min_width) return BoxReason::undecided_contract;
        return std::nullopt;
    }
    double widest = 0;
    for (const I& x : box.x) widest = std::max(widest, width_upper(x));
    if (widest < context.min_width) return BoxReason::undecided_width;
    return std::nullopt;
}

std::array<ChartBox<I>, 2> split_box(const ChartBox<I>& box) {
    int widest = 0;
    for (int k = 1; k < chart_dimension; ++k)
        if (width_upper(box.x[k]) > width_upper(box.x[widest])) widest = k;
    std::array<ChartBox<I>, 2> halves{box, box};
    const I middle = midpoint(box.x[widest]);
    halves[0].x[widest] = hull(lower_point(box.x[widest]), middle);
    halves[1].x[widest] = hull(middle, upper_point(box.x[widest]));
    halves[0].depth = halves[1].depth = box.depth + 1;
    return halves;
}

}  // namespace superpack
