#include "superpack/problems/crossover/crossover_json.hpp"

namespace superpack {

namespace {

const char* sign_text(int sign) { return sign < 0 ? "negative" : sign > 0 ? "positive" : "undecided"; }

template <class I>
Json optional_json(const std::optional<I>& x) {
    return x ? enclosure_json(*x) : Json(nullptr);
}

Json pieces_json(const std::vector<SignPiece>& pieces) {
    Json list = Json::array();
    std::size_t counts[4] = {0, 0, 0, 0};
    for (const SignPiece& piece : pieces) {
        list.push_back(sign_piece_json(piece));
        ++counts[static_cast<int>(piece.claim)];
    }
    return Json{{"count", pieces.size()}, {"negative", counts[0]}, {"positive", counts[1]}, {"root", counts[2]},
                {"undecided", counts[3]}, {"list", list}};
}

}  // namespace

Json sign_piece_json(const SignPiece& piece) {
    // The endpoints are doubles; "exact" gives them as fractions so a checker can rebuild them.
    const Json exact{{"lo", rational_text(Rational(piece.p.lower()))}, {"hi", rational_text(Rational(piece.p.upper()))}};
    return Json{{"p", enclosure_json(piece.p)}, {"p_exact", exact}, {"claim", to_string(piece.claim)}, {"reason", piece.reason},
                {"difference", optional_json(piece.difference)}, {"derivative", optional_json(piece.derivative)}};
}

template <class I>
Json density_slope_json(const DensitySlope<I>& slope) {
    Json parameters = Json::object();
    for (const auto& parameter : slope.parameters) parameters[parameter.name] = enclosure_json(parameter.value);
    Json result{{"family", to_string(slope.family)},
                {"certified", slope.status == Outcome::proved},
                {"parameters", parameters},
                {"parameter_slope", optional_json(slope.parameter_slope)},
                {"phi", optional_json(slope.phi)},
                {"slope", optional_json(slope.slope)}};
    if (!slope.message.empty()) result["message"] = slope.message;
    return result;
}

template <class I>
Json printed_check_json(const PrintedCheck<I>& check) {
    return Json{{"printed", check.printed}, {"as_truncated", agreement_word(check.truncated)},
                {"as_rounded", agreement_word(check.rounded)}};
}

template <class I>
Json newton_json(const NewtonResult<I>& newton) {
    return Json{{"status", to_string(newton.status)},      {"initial_box", enclosure_json(newton.initial_box)},
                {"box", enclosure_json(newton.box)},         {"derivative", enclosure_json(newton.derivative)},
                {"existence", newton.existence},             {"uniqueness", newton.uniqueness},
                {"iterations", newton.iterations},           {"reason", newton.reason}};
}

template <class I>
Json cubic_crossover_json(const CubicCrossover<I>& crossover) {
    Json result{{"kind", "cubic"},
                {"certified", crossover.certified},
                {"difference", "g(p) = phi_C1(p) - phi_C0(p)"},
                {"p", optional_json(crossover.p)},
                {"phi", optional_json(crossover.phi)},
                {"phi_C0", optional_json(crossover.phi_c0)},
                {"phi_C1", optional_json(crossover.phi_c1)},
                {"unique_on", Json::array({"1", "10"})},
                {"sign_left", sign_text(crossover.sign_left)},
                {"sign_right", sign_text(crossover.sign_right)},
                {"densest_left", crossover.sign_left < 0 ? "C0" : crossover.sign_left > 0 ? "C1" : "undecided"},
                {"densest_right", crossover.sign_right < 0 ? "C0" : crossover.sign_right > 0 ? "C1" : "undecided"}};
    if (!crossover.message.empty()) result["message"] = crossover.message;
    if (crossover.newton) result["newton"] = newton_json(*crossover.newton);
    Json at_one{{"lemma", "g(1) = 0 exactly: at p = 1 both C0 (s = (2 - sqrt2)/4) and C1 (s = sqrt2/6) are the FCC "
                          "lattice, |det| = 4 sqrt2 (NOTES.md)"}};
    if (crossover.c0_at_1) at_one["C0"] = density_slope_json(*crossover.c0_at_1);
    if (crossover.c1_at_1) at_one["C1"] = density_slope_json(*crossover.c1_at_1);
    result["at_p_equals_1"] = at_one;
    result["pieces"] = pieces_json(crossover.pieces);
    Json paper = Json::object();
    if (crossover.p) paper["p"] = printed_check_json(check_printed(*crossover.p, "1.1509"));
    if (crossover.phi) paper["phi"] = printed_check_json(check_printed(*crossover.phi, "0.7596"));
    result["paper"] = paper;
    return result;
}

template <class I>
Json octahedral_crossover_json(const OctahedralCrossover<I>& crossover) {
    Json result{{"kind", "octahedral"},
                {"certified", crossover.certified},
                {"equation", "Eq. (6): 2 (1 - 2^(1-2p))^(1/(2p)) - 1 = 0"},
                {"p", optional_json(crossover.p)},
                {"phi", optional_json(crossover.phi)},
                {"ln3_over_ln4", optional_json(crossover.ln3_over_ln4)},
                {"root_overlaps_ln3_over_ln4", agreement_word(crossover.closed_form)},
                {"unique_on", Json::array({"1/2", "1"})}};
    if (!crossover.message.empty()) result["message"] = crossover.message;
    if (crossover.newton) result["newton"] = newton_json(*crossover.newton);
    result["pieces"] = pieces_json(crossover.pieces);
    result["O0"] = family_json(crossover.o0);
    Json o1{{"limit", "the Minkowski branch of Eq. (12) at p*_o: (q, s) = (0, 1), l = 1/2 exactly (NOTES.md); "
                      "a fold of Eq. (12), so it is evaluated in closed form, not by Newton"}};
    Json residuals = Json::array();
    for (const auto& residual : crossover.o1_residuals) residuals.push_back(enclosure_json(residual));
    o1["residuals"] = residuals;
    if (crossover.o1_basis_at_root) {
        Json basis = Json::array();
        for (const auto& row : *crossover.o1_basis_at_root) {
            Json vector = Json::array();
            for (const auto& x : row) vector.push_back(enclosure_json(x));
            basis.push_back(vector);
        }
        o1["basis"] = basis;
    }
    o1["determinant"] = optional_json(crossover.o1_determinant);
    o1["phi"] = optional_json(crossover.o1_phi);
    result["O1"] = o1;
    result["same_lattice"] = Json{{"U", Json::array({Json::array({2, -1, -1}), Json::array({0, 1, 0}),
                                                      Json::array({1, 0, -1})})},
                                  {"claim", "B_O0 = U B_O1 at p*_o, det U = -1"},
                                  {"enclosures_consistent", crossover.same_lattice}};
    result["densities_meet"] = agreement_word(crossover.densities_meet);
    Json paper = Json::object();
    if (crossover.p) paper["p"] = printed_check_json(check_printed(*crossover.p, "0.7924"));
    if (crossover.phi) paper["phi"] = printed_check_json(check_printed(*crossover.phi, "0.7959"));
    result["paper"] = paper;
    return result;
}

template <class I>
Json sphere_slopes_json(const SphereSlopes<I>& slopes) {
    Json result{{"a_minus", optional_json(slopes.a_minus)},
                {"a_minus_family", "O0"},
                {"a_plus", optional_json(slopes.a_plus)},
                {"a_plus_family", slopes.a_plus_family.empty() ? "undecided" : slopes.a_plus_family},
                {"families", Json::array({density_slope_json(slopes.c0), density_slope_json(slopes.c1),
                                          density_slope_json(slopes.o0)})}};
    result["paper"] = Json{
        {"a_minus", Json{{"closed_form", "-(pi/(12 sqrt2)) [ln 64 + 8 + 4 psi(1/2) + 2 psi(3/2) - 6 psi(5/2)]"},
                         {"closed_form_value", optional_json(slopes.closed_minus)},
                         {"certified_vs_closed_form", agreement_word(slopes.minus_vs_closed)},
                         {"certified_vs_printed", printed_check_json(slopes.minus_printed)}}},
        {"a_plus", Json{{"closed_form", "-(pi/(12 sqrt2)) [24 + ln 8 + 4 psi(1/2) + 2 psi(3/2) - 6 psi(5/2)]"},
                        {"closed_form_value", optional_json(slopes.closed_plus)},
                        {"certified_vs_closed_form", agreement_word(slopes.plus_vs_closed)},
                        {"certified_vs_printed", printed_check_json(slopes.plus_printed)},
                        {"closed_form_vs_printed", printed_check_json(slopes.closed_plus_printed)}}}};
    return result;
}

template Json density_slope_json(const DensitySlope<DInterval>&);
template Json density_slope_json(const DensitySlope<Ball>&);
template Json cubic_crossover_json(const CubicCrossover<DInterval>&);
template Json cubic_crossover_json(const CubicCrossover<Ball>&);
template Json octahedral_crossover_json(const OctahedralCrossover<DInterval>&);
template Json octahedral_crossover_json(const OctahedralCrossover<Ball>&);
template Json sphere_slopes_json(const SphereSlopes<DInterval>&);
template Json sphere_slopes_json(const SphereSlopes<Ball>&);

}  // namespace superpack
