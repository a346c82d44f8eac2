#include "critical_box.hpp"

#include <algorithm>
#include <cmath>

#include "superpack/arith/contract.hpp"
#include "superpack/problems/critical/critical_contraction.hpp"

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

// b1 . (b2 + b3 - b1) = b1 . (b2 + b3) - |b1|^2, whose sign the relabelling
// (b1, b2, b3) -> (b1, b1 - b2, b1 - b3) of A3 reverses (12.2): the chart keeps it >= 0.
I sigma_form(const Basis<I>& b) {
    I sum = b[0][0] * (b[1][0] + b[2][0] - b[0][0]);
    for (int j = 1; j < 3; ++j) sum = sum + b[0][j] * (b[1][j] + b[2][j] - b[0][j]);
    return sum;
}

// The short-vector candidate (not a configuration vector) whose sum |(c B)_j / 2|^(2p) has the
// least upper end over the box, when that end is below 4 (a cut of h_c >= 0 is then worth trying).
std::optional<Coefficients> likeliest_short(const ChartBox<I>& box, const Basis<I>& basis, const BoxContext& context) {
    const std::array<Coefficients, 6> triples = configuration_triples(box.configuration);
    double least = 4;
    std::optional<Coefficients> chosen;
    for (const Coefficients& c : context.short_candidates) {
        if (std::any_of(triples.begin(), triples.end(), [&](const Coefficients& t) { return representative(t) == c; }))
            continue;
        const double upper = half_norm_power(combination(basis, c), context.two_p).upper();
        if (upper < least) {
            least = upper;
            chosen = c;
        }
    }
    return chosen;
}

// Some coordinate of v certainly larger in size than `bound` (an upper end).
bool certainly_longer(const std::array<I, 3>& v, const I& bound) {
    for (const I& x : v)
        if (certainly_less(upper_point(bound), abs(x))) return true;
    return false;
}

// The closing region test: some image's W^-1 B P^-1 lies inside its region (its index).
std::optional<std::size_t> closing_image(const Basis<I>& basis, const BoxContext& context) {
    for (std::size_t index = 0; index < context.images->size(); ++index) {
        const ChartImage& image = (*context.images)[index];
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
        if (region_contains(region, unmapped)) return index;
    }
    return std::nullopt;
}

int widest_coordinate(const ChartPoint& x) {
    int widest = 0;
    for (int k = 1; k < chart_dimension; ++k)
        if (width_upper(x[k]) > width_upper(x[widest])) widest = k;
    return widest;
}

double widest_width(const ChartPoint& x) { return width_upper(x[widest_coordinate(x)]); }

// A contraction that removed at least this share of some coordinate's width is followed by
// another evaluation of the smaller box (its slopes are tighter), at most `contraction_rounds`.
constexpr double worth_another_round = 0.25;
constexpr int contraction_rounds = 4;

// The coordinate to split a box at that the contractors left: the one whose term |dL/dx_k| w_k
// of the Lagrangian's mean-value form is largest (the "smear" rule: the Lagrangian decides the
// determinant leaves, most of all), among the coordinates at least 2^-20 as wide as the widest;
// the widest when every such term is 0. Any choice is sound (both halves are decided); this one
// more than halves the boxes at p = 2 against the widest coordinate (NOTES.md 12.10).
int smear_coordinate(const LinearForm& lagrange, const ChartPoint& x) {
    const int widest = widest_coordinate(x);
    const double floor = std::ldexp(width_upper(x[widest]), -20);
    int chosen = widest;
    double largest = 0;
    for (int k = 0; k < chart_dimension; ++k) {
        const double width = width_upper(x[k]);
        if (!(width >= floor) || width == 0) continue;
        const double score = std::max(std::fabs(lagrange.slope[k].lower()), std::fabs(lagrange.slope[k].upper())) * width;
        if (score > largest) {
            largest = score;
            chosen = k;
        }
    }
    return chosen;
}

// Reasons 1-4 of NOTES 12.3 and the contractors: a leaf's reason, or nothing with x the box
// contracted, `basis` an enclosure of the chart basis over the (uncontracted) box and `split`
// the coordinate to split x at.
std::optional<BoxReason> first_order_tests(const ChartBox<I>& box, ChartPoint& x, Basis<I>& basis, int& split,
                                           const BoxContext& context, std::string* trace) {
    const I& two_p = context.two_p;
    // The leaf's letter in the certificate's tree grammar (NOTES.md 12.8).
    auto leaf = [trace](BoxReason reason, const char* letter) {
        if (trace) *trace += letter;
        return reason;
    };
    // The swap of b2 and b3 keeps b1 and both configurations (12.2): where v2 and v3 share a
    // face, the chart keeps a2 <= a3.
    if (box.face2 == box.face3 && certainly_less(box.x[4], box.x[2])) return leaf(BoxReason::symmetric, "m");
    // Naive enclosures over the box.
    basis = chart_basis(box.x, box.face2, box.face3, two_p);
    const std::array<I, 3> g = chart_equations(basis, box.configuration, two_p);
    for (const I& value : g)
        if (!contains_zero(value)) return leaf(BoxReason::no_configuration, "n");
    for (const Coefficients& c : max_norm_orbit(box.configuration))
        if (certainly_longer(combination(basis, c), basis[0][0])) return leaf(BoxReason::relabelled, "r");
    if (box.configuration == MinkowskiCase::a3 && certainly_less(sigma_form(basis), context.sigma_margin))
        return leaf(BoxReason::symmetric, "m");
    if (certainly_less(abs(determinant(basis)), context.volume)) return leaf(BoxReason::volume, "v");

    const ChartForms forms = chart_forms(box, two_p);
    for (const LinearForm& equation : forms.equations)
        if (!contains_zero(enclose(equation, box.x, forms.center))) return leaf(BoxReason::no_configuration, "n");
    for (int r = 0; r < 3; ++r)
        for (int j = 0; j < 3; ++j) intersect(basis[r][j], basis[r][j], forms.basis[r][j]);
    // On the configuration's points the Lagrangian is det (NOTES 12.3, 4.).
    const LinearForm lagrange = lagrangian(forms);
    const I value = enclose(lagrange, box.x, forms.center);
    // With a relative margin of 2^-40: the checker's multipliers differ from these in the last
    // bits, and it must prove the same leaf (NOTES.md 12.8).
    const I above = context.threshold * context.margin_above, below = lower_point(context.volume) * context.margin_below;
    if (certainly_less(above, value) || certainly_less(value, -above)) return leaf(BoxReason::determinant, "d");
    if (certainly_less(abs(value), below)) return leaf(BoxReason::volume, "v");

    // Contractors: the part cut off holds no configuration point (g), or only configuration
    // points with |det| > T or |det| < V(K) (the Lagrangian, which is det there): the facts of
    // the no_configuration, determinant and volume leaves, proved on that part as a whole.
    if (trace) *trace += 'C';
    if (!contract_to_configuration(forms, x, trace)) return leaf(BoxReason::no_configuration, ";E");
    const I low = lower_point(context.volume), high = context.threshold;
    if (!contract_linear(lagrange, {hull(low, high), hull(-high, -low)}, x, forms.center, "3", trace))
        return leaf(BoxReason::determinant, ";E");
    // The short-vector cut: the lattice vector c B likeliest to be short (the least upper end of
    // sum |(c B)_j / 2|^(2p) over the box, c not a configuration vector) is not, on what is kept.
    if (const std::optional<Coefficients> c = likeliest_short(box, basis, context)) {
        const std::string name{'4', static_cast<char>('2' + (*c)[0]), static_cast<char>('2' + (*c)[1]), static_cast<char>('2' + (*c)[2])};
        if (!contract_linear(short_vector_form(forms, *c, two_p), {context.admissible}, x, forms.center, name, trace))
            return leaf(BoxReason::short_vector, ";E");
    }
    if (trace) *trace += ';';
    // Where |det| < T at the centre only a short vector (or the volume) can decide the box, and
    // the Lagrangian's slopes say nothing about that test: there the widest coordinate is split.
    split = certainly_less(abs(lagrange.at_center), high) ? widest_coordinate(x) : smear_coordinate(lagrange, x);
    return std::nullopt;
}

// Reasons 5-6 of NOTES 12.3 on a box whose chart basis lies in `basis`.
std::optional<BoxReason> lattice_tests(const ChartBox<I>& box, const Basis<I>& basis, const BoxContext& context,
                                       std::string* trace) {
    if (const std::optional<std::size_t> image = closing_image(basis, context)) {
        if (trace) *trace += 'c' + std::to_string(*image) + '.';
        return BoxReason::closing_region;
    }
    const DoubleField field;
    const I one = field.integer(1);
    const std::array<Coefficients, 6> triples = configuration_triples(box.configuration);
    for (const Coefficients& c : context.short_candidates) {
        // The configuration's own vectors have norm 2 on M (and below 2 only off M, where g excludes).
        if (std::any_of(triples.begin(), triples.end(), [&](const Coefficients& t) { return representative(t) == c; }))
            continue;
        const std::array<I, 3> v = combination(basis, c);
        if (certainly_longer(v, field.integer(2))) continue;
        if (certainly_less(half_norm_power(v, context.two_p), one)) {
            if (trace) *trace += std::string{'s', static_cast<char>('2' + c[0]), static_cast<char>('2' + c[1]), static_cast<char>('2' + c[2])};
            return BoxReason::short_vector;
        }
    }
    return std::nullopt;
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
    context.margin_above = field.integer(1) + field.rational(Rational(1, 1L << 40));
    context.margin_below = field.integer(1) - field.rational(Rational(1, 1L << 40));
    context.sigma_margin = -field.rational(Rational(1, 1L << 40));
    context.admissible = hull(field.integer(0), DInterval(1e300));
    for (long a = -2; a <= 2; ++a)
        for (long b = -2; b <= 2; ++b)
            for (long c = -2; c <= 2; ++c) {
                const Coefficients triple{a, b, c};
                if (triple == Coefficients{0, 0, 0} || representative(triple) != triple) continue;
                context.short_candidates.push_back(triple);
            }
    return context;
}

BoxDecision decide_box(const ChartBox<I>& start, const BoxContext& context, std::string* trace) {
    BoxDecision decision{std::nullopt, start};
    ChartBox<I>& box = decision.box;
    std::size_t round_start = trace ? trace->size() : 0;
    // Whether the rounds decided the box by the first-order tests alone.
    const Contracted<bool> rounds = within_contract([&] {
        for (int round = 1;; ++round) {
            if (trace) round_start = trace->size();
            ChartPoint x = box.x;
            Basis<I> basis;
            int split = -1;
            decision.reason = first_order_tests(box, x, basis, split, context, trace);
            if (decision.reason) return true;
            bool shrunk = false;
            for (int k = 0; k < chart_dimension; ++k)
                shrunk = shrunk || width_upper(x[k]) < (1 - worth_another_round) * width_upper(box.x[k]);
            if (!shrunk || round == contraction_rounds) {
                decision.reason = lattice_tests(box, basis, context, trace);
                box.x = x;
                box.split = split;
                return false;
            }
            box.x = x;
        }
    });
    if (rounds.status == ContractStatus::too_wide) {
        // A power's contract refused an enclosure (it cannot on this chart, where every base of
        // a fractional power is a coordinate or a sum in [1, 3]): split, and at the floor undecided.
        // The round that threw leaves nothing in the trace: the split is of the box it started with.
        if (trace) trace->resize(round_start);
        box.split = -1;
        if (widest_width(box.x) < context.min_width) decision.reason = BoxReason::undecided_contract;
        return decision;
    }
    if (*rounds.value) return decision;
    if (!decision.reason && widest_width(box.x) < context.min_width) decision.reason = BoxReason::undecided_width;
    return decision;
}

int split_coordinate(const ChartBox<I>& box) { return box.split >= 0 ? box.split : widest_coordinate(box.x); }

std::array<ChartBox<I>, 2> split_box(const ChartBox<I>& box) {
    const int k = split_coordinate(box);
    std::array<ChartBox<I>, 2> halves{box, box};
    const I middle = midpoint(box.x[k]);
    halves[0].x[k] = hull(lower_point(box.x[k]), middle);
    halves[1].x[k] = hull(middle, upper_point(box.x[k]));
    halves[0].depth = halves[1].depth = box.depth + 1;
    halves[0].split = halves[1].split = -1;
    return halves;
}

}  // namespace superpack
