// The superdisk driver: the two PRL lattices and the certified minimal-hexagon optimum.
// Method and proofs: NOTES.md section 7.
#include "superpack/problems/superdisk/superdisk.hpp"

#include <algorithm>
#include <optional>

#include "superpack/solve/minimise.hpp"

namespace superpack {

const char* to_string(PieceVerdict verdict) {
    switch (verdict) {
        case PieceVerdict::discarded: return "discarded";
        case PieceVerdict::monotone: return "monotone";
        case PieceVerdict::bounded: return "bounded";
        case PieceVerdict::undecided: return "undecided";
    }
    return "undecided";
}

const char* to_string(LowerBoundMethod method) {
    switch (method) {
        case LowerBoundMethod::naive: return "naive";
        case LowerBoundMethod::naive_and_mean_value: return "naive_and_mean_value";
        case LowerBoundMethod::left_end: return "left_end";
        case LowerBoundMethod::right_end: return "right_end";
        case LowerBoundMethod::a_priori: return "a_priori";
    }
    return "naive";
}

const char* to_string(OptimumStatus status) {
    switch (status) {
        case OptimumStatus::certified: return "certified";
        case OptimumStatus::undecided: return "undecided";
        case OptimumStatus::not_applicable: return "not_applicable";
    }
    return "undecided";
}

const Rational superdisk_largest_p(1000000);

namespace {

// A floating-point guess of v(t) (only a starting box, re-verified by Krawczyk).
// v is the boundary point at polar angle phi in (theta, theta + pi) where the q-norm of
// v - u crosses 1 (it grows from 0 at v = u to 2 at v = -u): bisection, then Newton steps.
std::array<double, 2> guess_v(double t, double q) {
    const double x = boundary_x(t, q), y = t * x;
    const double theta = std::atan2(y, x), pi = 3.141592653589793;
    // The boundary point in direction (c, s): scaled by the larger of |c|, |s| first, so that the
    // q-th powers neither underflow (both below 1 in size) nor overflow at large q.
    auto on_boundary = [q](double angle) {
        const double c = std::cos(angle), s = std::sin(angle);
        const double large = std::max(std::fabs(c), std::fabs(s)), small = std::min(std::fabs(c), std::fabs(s));
        const double r = std::exp(-std::log1p(std::pow(small / large, q)) / q) / large;
        return std::array<double, 2>{r * c, r * s};
    };
    double lo = theta, hi = theta + pi;
    for (int step = 0; step < 60; ++step) {
        const double mid = 0.5 * (lo + hi);
        const auto v = on_boundary(mid);
        (std::pow(std::fabs(v[0] - x), q) + std::pow(std::fabs(v[1] - y), q) < 1 ? lo : hi) = mid;
    }
    auto [a, b] = on_boundary(0.5 * (lo + hi));
    // Newton steps, each kept only if it lowers the residual (at large q the bisection is often
    // as good as double allows, and a step on the nearly singular system can only lose).
    auto residual = [&](double x0, double x1) {
        const auto f = contact_equations(x0, x1, t, q);
        return std::max(std::fabs(f[0]), std::fabs(f[1]));
    };
    for (int step = 0; step < 4; ++step) {
        const auto fa = contact_equations(variable(a), constant(b), constant(t), q);
        const auto fb = contact_equations(constant(a), variable(b), constant(t), q);
        const double j00 = fa[0].derivative, j01 = fb[0].derivative, j10 = fa[1].derivative, j11 = fb[1].derivative;
        const double det = j00 * j11 - j01 * j10;
        if (!(std::fabs(det) > 0)) break;
        const double f0 = fa[0].value, f1 = fa[1].value;
        const double da = (j11 * f0 - j01 * f1) / det, db = (-j10 * f0 + j00 * f1) / det;
        if (!std::isfinite(da) || !std::isfinite(db) || !(residual(a - da, b - db) < residual(a, b))) break;
        a -= da;
        b -= db;
    }
    return {a, b};
}

template <class I>
struct Evaluation {
    explicit Evaluation(const I& zero) : value(zero), derivative(zero) {}
    RootStatus status = RootStatus::undecided;
    std::vector<I> v;
    std::vector<I> search_box;  // where K(X) in int X was proved
    I value;       // D on the piece (naive enclosure)
    I derivative;  // D' on the piece; contains everything when unknown
    bool derivative_known = false;
    std::string reason;
};

// Certifies v(t) for all t in `piece` and encloses D and D' there.
template <class I>
Evaluation<I> evaluate(const I& piece, const I& q, double margin, bool with_derivative = true) {
    const auto field = field_of(piece);
    Evaluation<I> result(field.integer(0));
    const double qd = mid_double(q);
    const double lo = mid_double(lower_point(piece)), hi = mid_double(upper_point(piece));
    const auto g0 = guess_v(lo, qd), g1 = guess_v(hi, qd);
    std::vector<I> box;
    if (!std::isfinite(g0[0] + g0[1] + g1[0] + g1[1])) {
        result.reason = "no floating-point guess for v";
        return result;
    }
    for (int k = 0; k < 2; ++k) {
        const double low = std::min(g0[k], g1[k]), high = std::max(g0[k], g1[k]);
        const double pad = 0.5 * (high - low) + margin;
        box.push_back(from_doubles(piece, low - pad, high + pad));
    }
    const ContactSystem<I> system{piece, q};
    const KrawczykResult<I> proof = krawczyk_isolate(system, box, 0.0, 40);
    result.status = proof.status;
    result.reason = proof.reason;
    if (proof.status != RootStatus::unique) return result;
    result.v = proof.box;
    result.search_box = proof.initial_box;
    const I& a = result.v[0];
    const I& b = result.v[1];
    result.value = hexagon_determinant(a, b, piece, q);
    if (!with_derivative) return result;
    // D'(t) = D_t + D_a a' + D_b b', with (a', b') = -J^{-1} F_t (implicit function theorem).
    const auto fa = contact_equations(variable(a), constant(b), constant(piece), q);
    const auto fb = contact_equations(constant(a), variable(b), constant(piece), q);
    const auto ft = contact_equations(constant(a), constant(b), variable(piece), q);
    const I jacobian = fa[0].derivative * fb[1].derivative - fb[0].derivative * fa[1].derivative;
    if (contains_zero(jacobian)) {
        result.reason = "Jacobian of the contact system may vanish";
        return result;
    }
    const I da = -(fb[1].derivative * ft[0].derivative - fb[0].derivative * ft[1].derivative) / jacobian;
    const I db = -(-fa[1].derivative * ft[0].derivative + fa[0].derivative * ft[1].derivative) / jacobian;
    const Jet<I> d_a = hexagon_determinant(variable(a), constant(b), constant(piece), q);
    const Jet<I> d_b = hexagon_determinant(constant(a), variable(b), constant(piece), q);
    const Jet<I> d_t = hexagon_determinant(constant(a), constant(b), variable(piece), q);
    result.derivative = d_t.derivative + d_a.derivative * da + d_b.derivative * db;
    result.derivative_known = true;
    return result;
}

template <class I>
HexagonLattice<I> lattice_at(const I& t, const I& q, const I& area) {
    const auto field = field_of(t);
    HexagonLattice<I> lattice(field.integer(0));
    lattice.t = t;
    if (contains(field.integer(0), t)) {
        // t = 0 (Lambda1): v = (1/2, y1) in closed form; its "search box" is that point.
        const I half = field.integer(1) / field.integer(2), height = axis_height(q), two = field.integer(2);
        lattice.status = RootStatus::unique;
        lattice.reason = "closed form at t = 0: v = (1/2, (1 - 2^-q)^(1/q))";
        lattice.search_box = {half, height};
        lattice.basis = {{{two, field.integer(0)}, {field.integer(1), two * height}}};
        lattice.determinant = field.integer(4) * height;
        lattice.phi = area / lattice.determinant;
        return lattice;
    }
    const Evaluation<I> at = evaluate(t, q, 1e-9, false);
    lattice.status = at.status;
    lattice.reason = at.reason;
    if (at.status != RootStatus::unique) return lattice;
    lattice.search_box = at.search_box;
    const I two = field.integer(2);
    const I x = boundary_x(t, q);
    lattice.basis = {{{two * x, two * t * x}, {two * at.v[0], two * at.v[1]}}};
    lattice.determinant = field.integer(4) * at.value;
    lattice.phi = area / lattice.determinant;
    return lattice;
}

template <class I>
bool enclosures_meet(const I& a, const I& b) {
    I meet = a;
    return intersect(meet, a, b);
}

template <class Field>
HexagonLattice<typename Field::Interval> hexagon_lattice_in(const Rational& t, const Rational& p, const Field& field) {
    const auto q = field.integer(2) * field.rational(p);
    return lattice_at(field.rational(t), q, enclose_ball_volume(field.rational(p), 2));
}

// The PRL's two lattices Lambda1 (t = 0) and Lambda0 (t = 1), for a convex disk only (a step
// of its own: every case of analyse_superdisk_in reports them).
template <class Field>
void enclose_families(SuperdiskReport<typename Field::Interval>& report, const Rational& p,
                      const typename Field::Interval& q, const Field& field) {
    if (p >= Rational(1, 2)) {
        report.lambda1 = lattice_at(field.integer(0), q, report.area);
        report.lambda0 = lattice_at(field.integer(1), q, report.area);
    } else {
        // For a concave disk u, v, v - u on the boundary does not make a packing (the lattice
        // overlaps: at p = 0.3 it would give phi > 1), and the PRL's concave constructions are
        // not implemented here.
        report.lambda0.reason = report.lambda1.reason = "not computed for p < 1/2 (concave disk)";
    }
}

// p < 1/2: the report says why no optimum is certified (its own step, so that the driver reads
// as the cases it tells apart).
template <class I>
void report_concave(SuperdiskReport<I>& report) {
    report.status = OptimumStatus::not_applicable;
    report.attained_by = "not_applicable";
    report.message = "p < 1/2: the superdisk is concave, so neither Fejes Toth's theorem nor the "
                     "inscribed-hexagon reduction applies; the two families are lattices with the contact "
                     "conditions only, not certified packings";
}

// p = 1/2: the square tiles, so the optimum is 1 without branch and bound (its own step, like
// report_concave).
template <class Field>
void report_square_tiling(SuperdiskReport<typename Field::Interval>& report, const Field& field) {
    const auto one = field.integer(1);
    // |x| + |y| <= 1 is a square: it tiles with the lattice (1,1), (1,-1), so phi = 1 = the bound.
    report.tiling = true;
    report.status = OptimumStatus::certified;
    report.optimal_phi = one;
    report.optimal_determinant = report.area;
    report.optimal_lattice.status = RootStatus::unique;
    report.optimal_lattice.t = one;
    report.optimal_lattice.basis = {{{one, one}, {one, -one}}};
    report.optimal_lattice.determinant = field.integer(2);
    report.optimal_lattice.phi = one;
    // Lambda1 (u = (1, 0), v = (1/2, 1/2)) is itself a tiling lattice of the square.
    report.attained_by = "tiling";
    if (report.lambda1.status == RootStatus::unique) {
        report.gap_lambda1 = one - report.lambda1.phi;
        if (enclosures_meet(report.lambda1.phi, one)) report.attained_by = "Lambda1";
    }
    report.message = "p = 1/2: the square |x|+|y|<=1 tiles the plane (lattice (1,1),(1,-1)), phi = 1";
}

// The better of the two certified families, D = det/4, as the branch and bound's first known
// value (a separate step: it seeds the search before any piece is bounded).
template <class Field>
std::optional<PointValue<typename Field::Interval, HexagonLattice<typename Field::Interval>>> best_family(
    const SuperdiskReport<typename Field::Interval>& report, const Field& field) {
    using I = typename Field::Interval;
    std::optional<PointValue<I, HexagonLattice<I>>> known;
    for (const HexagonLattice<I>* family : {&report.lambda1, &report.lambda0})
        if (family->status == RootStatus::unique) {
            const I d = family->determinant / field.integer(4);
            if (!known || mid_double(d) < mid_double(known->value)) known = PointValue<I, HexagonLattice<I>>{d, *family};
        }
    return known;
}

// The branch and bound's settings from the user's options (kept apart: the fixed widths below
// are part of the method, and bound_superdisk_piece reads min_undecided_width).
MinimiseOptions superdisk_search_options(const SuperdiskOptions& options) {
    MinimiseOptions search;
    search.relative_tolerance = options.relative_tolerance;
    search.max_pieces = options.max_pieces;
    // A piece whose contact system is not yet certified is split (its v(t) varies too much
    // for one Krawczyk box); below 1e-12 it is kept as undecided, never dropped,
    // unless the a priori bound below decides it.
    search.min_undecided_width = 1e-12;
    search.min_width = 1e-14;
    return search;
}

// A piece whose v(t) Krawczyk cannot follow (for large q, near t = 0) is bounded instead by
// a_priori_lower_bound, which needs no v: when that bound already exceeds the best lattice
// (the piece will be discarded), or when a piece holding t = 0 is too narrow to split.
template <class Field>
HexagonPiece<typename Field::Interval> a_priori_piece(HexagonPiece<typename Field::Interval> piece,
                                                      const typename Field::Interval& q, const Field& field) {
    using I = typename Field::Interval;
    const I one = field.integer(1);
    piece.verdict = PieceVerdict::bounded;
    piece.method = LowerBoundMethod::a_priori;
    piece.lower_bound = a_priori_lower_bound(piece.t, q);
    piece.reason = "a priori bound of D from the contact equations, for every v with det(u, v) > 0";
    // What the bound's proof shows of v = (a, b): -(1 - x) <= a <= x/2 and y1 <= b <= 1.
    const I x = boundary_x(piece.t, q);
    piece.v = {hull(lower_point(x) - one, upper_point(x) / field.integer(2)), hull(axis_height(q), one)};
    piece.search_box.clear();
    return piece;
}

// The branch and bound's bound on one piece of t in [0, 1]: a lower bound of D there, by
// monotonicity, the mean-value form or the a priori bound. `best`, the minimiser's best value
// so far, lets a piece bounded a priori be seen to be discarded. Its own function (not a lambda
// in analyse_superdisk_in): it is the method's core, read apart from the driver.
template <class Field>
BoundedBox<typename Field::Interval, HexagonPiece<typename Field::Interval>> bound_superdisk_piece(
    const std::vector<typename Field::Interval>& box, const std::optional<typename Field::Interval>& best,
    const typename Field::Interval& q, const typename Field::Interval& area, double min_undecided_width,
    const Field& field) {
    using I = typename Field::Interval;
    using Piece = HexagonPiece<I>;
    const I zero = field.integer(0);
    const I& t = box[0];
    Piece piece{t, PieceVerdict::undecided, zero, {}, zero, "", {}, LowerBoundMethod::naive, zero};
    auto bounded = [&](PieceVerdict verdict, std::string reason) {
        piece.verdict = verdict;
        piece.reason = std::move(reason);
        return BoundedBox<I, Piece>{box, true, piece.lower_bound, piece, piece.reason};
    };
    const Evaluation<I> at = evaluate(t, q, 1e-9 + 1e-3 * width_upper(t));
    if (at.status != RootStatus::unique) {
        piece.reason = "contact system not certified on the piece: " + at.reason;
        const Piece bounded_a_priori = a_priori_piece(piece, q, field);
        const bool too_narrow = width_upper(t) < min_undecided_width && contains(t, zero);
        if (too_narrow || (best && certainly_less(upper_point(*best), bounded_a_priori.lower_bound)))
            return BoundedBox<I, Piece>{box, true, bounded_a_priori.lower_bound, bounded_a_priori, bounded_a_priori.reason};
        return BoundedBox<I, Piece>{box, false, zero, piece, piece.reason};
    }
    piece.v = at.v;
    piece.search_box = at.search_box;
    piece.lower_bound = at.value;
    if (!at.derivative_known) return bounded(PieceVerdict::bounded, "naive enclosure of D (" + at.reason + ")");
    piece.derivative = at.derivative;
    const bool increasing = certainly_positive(at.derivative), decreasing = certainly_negative(at.derivative);
    if (increasing || decreasing) {
        const HexagonLattice<I> end = lattice_at(increasing ? lower_point(t) : upper_point(t), q, area);
        if (end.status == RootStatus::unique) {
            piece.lower_bound = end.determinant / field.integer(4);
            piece.method = increasing ? LowerBoundMethod::left_end : LowerBoundMethod::right_end;
            return bounded(PieceVerdict::monotone,
                           increasing ? "D' > 0: minimum at the left end" : "D' < 0: minimum at the right end");
        }
    }
    // Mean-value form around the midpoint, intersected with the naive enclosure.
    const I center = midpoint(t);
    const Evaluation<I> middle = evaluate(center, q, 1e-9, false);
    if (middle.status == RootStatus::unique) {
        const I form = middle.value + at.derivative * (t - center);
        I meet = form;
        if (intersect(meet, form, at.value)) {
            piece.lower_bound = meet;
            piece.method = LowerBoundMethod::naive_and_mean_value;
            piece.center = center;
        }
    }
    return bounded(PieceVerdict::bounded, "naive and mean-value enclosures of D");
}

// The minimiser's leaves become the report's pieces, sorted by t; returns the pieces that may
// hold a minimiser (a step of its own: the report's pieces and the argmin come from one pass).
template <class I>
std::vector<I> record_pieces(SuperdiskReport<I>& report, const Minimum<I, HexagonPiece<I>, HexagonLattice<I>>& minimum) {
    using Piece = HexagonPiece<I>;
    std::vector<I> near_optimal;  // pieces that may hold a minimiser
    for (const auto& leaf : minimum.leaves) {
        Piece piece = leaf.data;
        if (leaf.fate == LeafFate::discarded) {
            piece.verdict = PieceVerdict::discarded;
            piece.reason = "lower bound of D above the determinant of a certified lattice; " + piece.reason;
        } else if (leaf.fate == LeafFate::candidate) {
            near_optimal.push_back(piece.t);
        }
        report.pieces.push_back(piece);
    }
    std::sort(report.pieces.begin(), report.pieces.end(), [](const Piece& x, const Piece& y) {
        return mid_double(lower_point(x.t)) < mid_double(lower_point(y.t));
    });
    return near_optimal;
}

// Merge touching near-optimal pieces into the components of the argmin enclosure (a step of its
// own: name_attaining_families reads the components).
template <class I>
void merge_argmin(SuperdiskReport<I>& report, std::vector<I> near_optimal) {
    std::sort(near_optimal.begin(), near_optimal.end(),
              [](const I& a, const I& b) { return mid_double(lower_point(a)) < mid_double(lower_point(b)); });
    for (const I& t : near_optimal) {
        if (!report.argmin_t.empty() && enclosures_meet(report.argmin_t.back(), t))
            report.argmin_t.back() = hull(report.argmin_t.back(), t);
        else
            report.argmin_t.push_back(t);
    }
}

// Which of Lambda0 and Lambda1 attain the certified optimum, and each one's gap to it (a step of
// its own: the verdict the report ends with).
template <class Field>
void name_attaining_families(SuperdiskReport<typename Field::Interval>& report, const Field& field) {
    using I = typename Field::Interval;
    auto in_argmin = [&](const I& t) {
        for (const I& component : report.argmin_t)
            if (contains(component, t)) return true;
        return false;
    };
    std::vector<std::string> names;
    auto judge = [&](const HexagonLattice<I>& family, const I& family_t, I& gap, const char* name) {
        if (family.status != RootStatus::unique) return;
        gap = report.optimal_phi - family.phi;
        if (enclosures_meet(family.phi, report.optimal_phi) && in_argmin(family_t)) names.push_back(name);
    };
    judge(report.lambda0, field.integer(1), report.gap_lambda0, "Lambda0");
    judge(report.lambda1, field.integer(0), report.gap_lambda1, "Lambda1");
    if (names.size() == 2)
        report.attained_by = "Lambda0 and Lambda1";
    else if (names.size() == 1)
        report.attained_by = names[0];
    else
        report.attained_by = "other";
}

template <class Field>
SuperdiskReport<typename Field::Interval> analyse_superdisk_in(const Rational& p, const Field& field,
                                                                const SuperdiskOptions& options) {
    using I = typename Field::Interval;
    if (p > superdisk_largest_p)
        throw InputError("superdisk: p = " + decimal_or_fraction_text(p) +
                         " is beyond the supported p <= 10^6 (near its minimum det(u, v) differs from 1 by about "
                         "(ln 2)^2/(2p)^2, below what the branch and bound resolves)");
    SuperdiskReport<I> report(field.integer(0));
    const I pp = field.rational(p);
    const I q = field.integer(2) * pp;
    report.area = enclose_ball_volume(pp, 2);
    enclose_families(report, p, q, field);
    const I zero = field.integer(0), one = field.integer(1);
    report.optimal_determinant = report.optimal_phi = zero;
    report.gap_lambda0 = report.gap_lambda1 = zero;
    report.optimal_lattice = report.lambda1;
    if (p < Rational(1, 2)) {
        report_concave(report);
        return report;
    }
    if (p == Rational(1, 2)) {
        report_square_tiling(report, field);
        return report;
    }

    // Best-first branch and bound over t in [0, 1] for min D(t) (solve/minimise.hpp).
    using Piece = HexagonPiece<I>;
    const std::optional<PointValue<I, HexagonLattice<I>>> known = best_family(report, field);
    const MinimiseOptions search = superdisk_search_options(options);
    auto value_at = [&](const std::vector<I>& t) -> std::optional<PointValue<I, HexagonLattice<I>>> {
        const HexagonLattice<I> lattice = lattice_at(t[0], q, report.area);
        if (lattice.status != RootStatus::unique) return std::nullopt;
        const I d = lattice.determinant / field.integer(4);
        return PointValue<I, HexagonLattice<I>>{d, lattice};
    };
    auto bound_piece = [&](const std::vector<I>& box, const std::optional<I>& best) {
        return bound_superdisk_piece(box, best, q, report.area, search.min_undecided_width, field);
    };
    const Minimum<I, Piece, HexagonLattice<I>> minimum =
        minimise<I, Piece, HexagonLattice<I>>({hull(zero, one)}, bound_piece, value_at, known, search);
    std::vector<I> near_optimal = record_pieces(report, minimum);
    if (minimum.best) report.optimal_lattice = minimum.best->witness;
    if (!minimum.certified) {
        report.status = OptimumStatus::undecided;
        report.attained_by = "undecided";
        report.message = "some pieces of the parameter range could not be certified";
        return report;
    }
    report.status = OptimumStatus::certified;
    report.optimal_determinant = field.integer(4) * *minimum.lowest;
    report.optimal_phi = report.area / report.optimal_determinant;
    merge_argmin(report, std::move(near_optimal));
    name_attaining_families(report, field);
    report.message = "min over t in [0,1] of 4 det(u(t), v(t)) certified by branch and bound";
    return report;
}

}  // namespace

SuperdiskReport<DInterval> analyse_superdisk(const Rational& p, const DoubleField& field, const SuperdiskOptions& options) {
    return analyse_superdisk_in(p, field, options);
}
SuperdiskReport<Ball> analyse_superdisk(const Rational& p, const BallField& field, const SuperdiskOptions& options) {
    return analyse_superdisk_in(p, field, options);
}
HexagonLattice<DInterval> enclose_hexagon_lattice(const Rational& t, const Rational& p, const DoubleField& field) {
    return hexagon_lattice_in(t, p, field);
}
HexagonLattice<Ball> enclose_hexagon_lattice(const Rational& t, const Rational& p, const BallField& field) {
    return hexagon_lattice_in(t, p, field);
}

}  // namespace superpack
