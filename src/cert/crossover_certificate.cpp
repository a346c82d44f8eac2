#include "superpack/cert/crossover_certificate.hpp"

#include <stdexcept>

#include "superpack/arith/decimal.hpp"
#include "superpack/cert/certificate_partition.hpp"

namespace superpack {

namespace {

template <class I>
const I& certified(const std::optional<I>& x, const char* what) {
    if (!x) throw std::runtime_error(std::string("certificate: ") + what + " is not certified");
    return *x;
}

// The Newton box of s (the smallest positive root of Eq. 2 or Eq. 9) at an exact p, with the
// first Newton step for the record; the checker adds that f is increasing on [0, box].
template <class I>
Json smallest_root_json(Family family, const FamilyLattice<I>& lattice, const I& p) {
    if (lattice.status != Outcome::proved || lattice.search.empty())
        throw std::runtime_error(std::string("certificate: ") + to_string(family) + " is not certified");
    const I& box = lattice.search.back().piece[0];
    auto equation = [&](const auto& s) { return cubic_equation(family, s, p); };
    const I derivative = equation(variable(box)).derivative;
    const I center = midpoint(box);
    return Json{{"kind", "smallest-root"},
                {"family", to_string(family)},
                {"box", exact_interval_json(box)},
                {"midpoint", exact_interval_json(center)},
                {"derivative", exact_interval_json(derivative)},
                {"image", exact_interval_json(center - equation(center) / derivative)},
                {"root", exact_interval_json(lattice.search.back().root[0])}};
}

// A Newton box for s over a piece: the certified root enclosure widened by half its width on
// each side (a tight box, so that a changed digit cannot leave a valid proof), proved again
// here; the wide box of the root search when that fails.
Json piece_root_json(const PieceRoot<Ball>& known) {
    const Ball half_width = (upper_point(known.root) - lower_point(known.root)) / field_of(known.root).integer(2);
    const Ball box = hull(lower_point(known.root) - half_width, upper_point(known.root) + half_width);
    auto equation = [&](const auto& s) { return cubic_equation(known.family, s, known.piece); };
    const NewtonResult<Ball> newton = newton_isolate(equation, box, 0.0, 50);
    const bool tight = newton.status == RootStatus::unique && certainly_positive(lower_point(box));
    return Json{{"box", exact_interval_json(tight ? box : known.root_box)}};
}

const char* sign_name(int sign) { return sign < 0 ? "negative" : "positive"; }
const char* denser(int sign) { return sign < 0 ? "C0" : "C1"; }

Json rational_matrix_json(const long (&m)[3][3], long denominator) {
    Json rows = Json::array();
    for (const auto& row : m) {
        Json entries = Json::array();
        for (long x : row) entries.push_back(rational_text(Rational(x, denominator)));
        rows.push_back(entries);
    }
    return rows;
}

}  // namespace

// ---- cubic ----------------------------------------------------------------------------

template <class Field>
Json cubic_crossover_certificate(const CubicCrossover<typename Field::Interval>& crossover, const Field& field,
                                 long digits) {
    if (!crossover.certified) throw std::runtime_error("certificate: the cubic crossover is not certified");
    const auto& p = certified(crossover.p, "p*_c");
    const auto& phi = certified(crossover.phi, "phi*_c");
    // The s boxes over each piece: certify_piece_root on the piece exactly as the partition
    // proved it (40-bit balls; crossover.cpp).
    const BallField partition_field{40};
    Json pieces = Json::array();
    for (const SignPiece& piece : crossover.pieces) {
        if (piece.claim == PieceClaim::undecided) throw std::runtime_error("certificate: an undecided piece");
        const Ball interval = from_doubles(partition_field.integer(0), piece.p.lower(), piece.p.upper());
        Json entry{{"p", exact_interval_json(piece.p)}, {"claim", to_string(piece.claim)}};
        for (const Family family : {Family::C0, Family::C1}) {
            const auto root = certify_piece_root(family, interval);
            if (!root) throw std::runtime_error("certificate: s not certified again over a piece");
            entry[std::string("s_") + to_string(family)] = piece_root_json(*root);
        }
        if (piece.claim == PieceClaim::root) entry["root"] = exact_interval_json(p);
        pieces.push_back(entry);
    }
    // At p = 1 (t = sqrt2/2) s_C0 = (2 - sqrt2)/4 and s_C1 = sqrt2/6, each as a + b sqrt2: both
    // lattices are FCC there and g(1) = 0 exactly.
    const Json at_start{{"kind", "sphere-point"},
                        {"p", "1"},
                        {"s_C0", Json{{"a", "1/2"}, {"b", "-1/4"}}},
                        {"s_C1", Json{{"a", "0"}, {"b", "1/6"}}}};
    const Json proof{{"kind", "sign-partition"}, {"at_start", at_start}, {"pieces", pieces}};
    Json claim{{"kind", "cubic-crossover"},
               {"data", Json{{"difference", "phi_C1(p) - phi_C0(p)"},
                             {"from", "1"},
                             {"to", "10"},
                             {"p", exact_interval_json(p)},
                             {"phi", exact_interval_json(phi)},
                             {"sign_left", sign_name(crossover.sign_left)},
                             {"sign_right", sign_name(crossover.sign_right)},
                             {"densest_left", denser(crossover.sign_left)},
                             {"densest_right", denser(crossover.sign_right)}}}};
    const Json inputs{{"from", "1"}, {"to", "10"}};
    return certificate_document(certificate_head("crossover cubic", field, digits), claim, inputs, proof);
}

// ---- octahedral -----------------------------------------------------------------------

template <class Field>
Json octahedral_crossover_certificate(const OctahedralCrossover<typename Field::Interval>& crossover,
                                      const Field& field, long digits) {
    using I = typename Field::Interval;
    if (!crossover.certified || !crossover.newton) throw std::runtime_error("certificate: the octahedral crossover is not certified");
    const auto& p = certified(crossover.p, "p*_o");
    const auto& phi = certified(crossover.phi, "phi*_o");
    // At p*_o: c = l = 1/2, (q, s) = (0, 1) (NOTES.md 6.3). The exact bases, checked against
    // the producer's enclosures before they are written.
    const long o0[3][3] = {{2, 0, 0}, {0, 2, 0}, {1, 1, 1}};
    const long o1[3][3] = {{1, 1, -1}, {0, 2, 0}, {0, 0, -2}};
    const long unimodular[3][3] = {{2, -1, -1}, {0, 1, 0}, {1, 0, -1}};
    const Basis<I>& o1_enclosure = certified(crossover.o1_basis_at_root, "the O1 limit basis");
    const Basis<I>& o0_enclosure = certified(crossover.o0.basis, "the O0 basis");
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!contains(o0_enclosure[i][j], field.integer(o0[i][j])) || !contains(o1_enclosure[i][j], field.integer(o1[i][j])))
                throw std::runtime_error("certificate: the exact bases at p*_o do not match the enclosures");
    const NewtonResult<I>& newton = *crossover.newton;
    const I& box = newton.initial_box;
    const I center = midpoint(box);
    const I one = field.integer(1), two = field.integer(2);
    const I image = center - (two * octahedral_height(center) - one) / newton.derivative;
    // Interval Newton on Eq. (6) itself; at p*_o, 3 = 4^p gives c = l = 1/2 and (q, s) = (0, 1)
    // solves Eq. (12), so B_O0 = U B_O1 (NOTES.md 6.3).
    const Json newton_leaf{{"kind", "newton"},
                           {"box", exact_interval_json(box)},
                           {"midpoint", exact_interval_json(center)},
                           {"derivative", exact_interval_json(newton.derivative)},
                           {"image", exact_interval_json(image)},
                           {"root", exact_interval_json(newton.box)}};
    const Json identity{{"kind", "lattice-identity"}};
    const Json proof{{"kind", "all"}, {"cases", Json::array({newton_leaf, identity})}};
    Json claim{{"kind", "octahedral-crossover"},
               {"data", Json{{"p", exact_interval_json(p)},
                             {"closed_form", "ln3/ln4"},
                             {"phi", exact_interval_json(phi)},
                             {"lattice", Json{{"O0", rational_matrix_json(o0, 1)},
                                              {"O1", rational_matrix_json(o1, 1)},
                                              {"unimodular", rational_matrix_json(unimodular, 1)},
                                              {"abs_determinant", "4"}}}}}};
    const Json inputs{{"from", "1/2"}, {"to", "1"}};
    return certificate_document(certificate_head("crossover octahedral", field, digits), claim, inputs, proof);
}

// ---- slopes ---------------------------------------------------------------------------

namespace {

template <class I>
Json family_slope_json(const DensitySlope<I>& slope, const char* parameter, const I& parameter_slope) {
    if (slope.status != Outcome::proved || slope.parameters.empty())
        throw std::runtime_error(std::string("certificate: the slope of ") + to_string(slope.family) + " is not certified");
    return Json{{parameter, exact_interval_json(slope.parameters.front().value)},
                {std::string("d") + parameter + "_dp", exact_interval_json(parameter_slope)},
                {"phi", exact_interval_json(certified(slope.phi, "phi"))},
                {"slope", exact_interval_json(certified(slope.slope, "the slope"))}};
}

template <class I>
Json readings_json(const PrintedCheck<I>& check) {
    return Json{{"as_truncated", agreement_word(check.truncated)}, {"as_rounded", agreement_word(check.rounded)}};
}

}  // namespace

template <class Field>
Json sphere_slopes_certificate(const SphereSlopes<typename Field::Interval>& slopes, const Field& field, long digits) {
    using I = typename Field::Interval;
    const I& a_minus = certified(slopes.a_minus, "a_minus");
    const I& a_plus = certified(slopes.a_plus, "a_plus");
    const I& closed_minus = certified(slopes.closed_minus, "the closed form of a_minus");
    const I& closed_plus = certified(slopes.closed_plus, "the closed form of a_plus");
    const Rational one(1);
    const I p = field.integer(1);
    Json cases = Json::array();
    for (const Family family : {Family::C0, Family::C1}) cases.push_back(smallest_root_json(family, enclose_family(family, one, field), p));
    // O0 needs no root: c = (1 - 2^(1-2p))^(1/(2p)); every slope by implicit differentiation.
    cases.push_back(Json{{"kind", "evaluation"}, {"family", "O0"}});
    const Json proof{{"kind", "all"}, {"cases", cases}};
    const I c_slope = octahedral_height(variable(p)).derivative;
    Json claim{
        {"kind", "sphere-slopes"},
        {"data",
         Json{{"p", "1"},
              {"C0", family_slope_json(slopes.c0, "s", certified(slopes.c0.parameter_slope, "ds/dp"))},
              {"C1", family_slope_json(slopes.c1, "s", certified(slopes.c1.parameter_slope, "ds/dp"))},
              {"O0", family_slope_json(slopes.o0, "c", c_slope)},
              {"a_minus", Json{{"family", "O0"}, {"value", exact_interval_json(a_minus)}}},
              {"a_plus", Json{{"family", slopes.a_plus_family}, {"value", exact_interval_json(a_plus)}}},
              {"paper",
               Json{{"a_minus", Json{{"printed", slopes.minus_printed.printed},
                                     {"closed_form", exact_interval_json(closed_minus)},
                                     {"certified_vs_closed_form", agreement_word(slopes.minus_vs_closed)},
                                     {"certified_vs_printed", readings_json(slopes.minus_printed)}}},
                    {"a_plus", Json{{"printed", slopes.plus_printed.printed},
                                    {"closed_form", exact_interval_json(closed_plus)},
                                    {"certified_vs_closed_form", agreement_word(slopes.plus_vs_closed)},
                                    {"certified_vs_printed", readings_json(slopes.plus_printed)},
                                    {"closed_form_vs_printed", readings_json(slopes.closed_plus_printed)}}}}}}}};
    const Json inputs{{"p", "1"}};
    return certificate_document(certificate_head("slopes", field, digits), claim, inputs, proof);
}

template Json cubic_crossover_certificate(const CubicCrossover<DInterval>&, const DoubleField&, long);
template Json cubic_crossover_certificate(const CubicCrossover<Ball>&, const BallField&, long);
template Json octahedral_crossover_certificate(const OctahedralCrossover<DInterval>&, const DoubleField&, long);
template Json octahedral_crossover_certificate(const OctahedralCrossover<Ball>&, const BallField&, long);
template Json sphere_slopes_certificate(const SphereSlopes<DInterval>&, const DoubleField&, long);
template Json sphere_slopes_certificate(const SphereSlopes<Ball>&, const BallField&, long);

}  // namespace superpack
