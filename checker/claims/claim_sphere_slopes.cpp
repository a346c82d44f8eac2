// Claim kind "sphere-slopes" (written by `superpack slopes --certificate`): the slopes
// dphi/dp at the sphere point p = 1 of C0, C1 (right of 1) and O0 (left of 1), a_minus (O0's),
// a_plus (the larger cubic slope: at p = 1 both cubic densities are pi/sqrt18, so the denser
// cubic family just right of 1 is the one with the larger slope), and the paper's closed forms
// and printed decimals with three-valued verdicts. The checker recomputes every slope by
// implicit differentiation in its own arithmetic (checker/formulas/equations_crossover.*). The paper's
// printed values and closed forms come from the checker's table (literature.hpp): the printed
// value named in the data must be the table's.
//
// Keys read: claim.data {p, C0 {s, ds_dp, phi, slope}, C1 {...}, O0 {c, dc_dp, phi, slope},
// a_minus {family, value}, a_plus {family, value}, paper {a_minus {printed, closed_form,
// certified_vs_closed_form, certified_vs_printed {as_truncated, as_rounded}}, a_plus {...,
// closed_form_vs_printed}}}; inputs {p}; proof {kind, cases [smallest-root C0, smallest-root C1,
// evaluation O0]} (smallest_root.hpp for the keys of a smallest-root case).
#include "checker/claims/literature.hpp"
#include "checker/core/render.hpp"
#include "checker/core/replay.hpp"
#include "checker/formulas/equations_crossover.hpp"
#include "checker/formulas/smallest_root.hpp"

namespace superpack_checker {

namespace {

// The stated enclosures of one family, each proved to contain the checker's value; returns the
// stated slope.
Real check_family(Context& context, const Json& data, const std::string& family, const std::string& parameter,
                  const ValueAndSlope& own_parameter, const ValueAndSlope& phi) {
    const std::string path = "claim.data." + family;
    const Json& stated = context.member(data, family, "claim.data");
    check_encloses(context, context.member(stated, parameter, path), path + "." + parameter, own_parameter.value);
    check_encloses(context, context.member(stated, "d" + parameter + "_dp", path), path + ".d" + parameter + "_dp",
                   own_parameter.slope);
    check_encloses(context, context.member(stated, "phi", path), path + ".phi", phi.value);
    return proved_enclosure(context, context.member(stated, "slope", path), path + ".slope", phi.slope);
}

// The verdicts {"as_truncated", "as_rounded"} at `path` for x against the printed digits: each
// must be the checker's or "undecided" (which claims nothing). Returns the stated pair.
std::pair<std::string, std::string> check_printed(Context& context, const std::string& digits, const Json& verdicts,
                                                  const Real& x, const std::string& path) {
    std::string stated[2];
    int k = 0;
    for (const auto& [name, truncated] : {std::pair<const char*, bool>{"as_truncated", true}, {"as_rounded", false}}) {
        stated[k] = context.string_at(verdicts, name, path);
        const std::string own = compare_with_printed(x, digits, truncated);
        context.require(stated[k] == "undecided" || stated[k] == own, path + "." + name,
                        "stated \"" + stated[k] + "\", the checker finds \"" + own + "\"");
        ++k;
    }
    return {stated[0], stated[1]};
}

// The printed value named in the data must be the table's (literature.hpp): the paper's digits
// are not an input.
std::string printed_at(Context& context, const Json& node, const PrintedValue& value, const std::string& path) {
    const std::string printed = context.string_at(node, "printed", path);
    const std::string digits = printed_digits(value);
    context.require(printed == digits, path + ".printed",
                    "\"" + printed.substr(0, 40) + "\" is not the paper's " + value.symbol + " = " + value.printed + " (" +
                        value.where + ")");
    return digits;
}

// "agree" when the enclosures meet, "disagree" when disjoint; the stated verdict must be it.
std::string check_overlap_verdict(Context& context, const Json& node, const std::string& key, const Real& a, const Real& b,
                                  const std::string& path) {
    const std::string stated = context.string_at(node, key, path);
    Real meet(a.precision());
    const std::string own = intersect(meet, a, b) ? "agree" : "disagree";
    context.require(stated == own, path + "." + key, "stated \"" + stated + "\", the checker finds \"" + own + "\"");
    return own;
}

// What the sentence says about one of the paper's slopes, from the verdicts checked above.
std::string paper_words(const PrintedValue& value, const Real& closed, const std::string& vs_closed,
                        const std::pair<std::string, std::string>& vs_printed,
                        const std::pair<std::string, std::string>* closed_vs_printed) {
    const std::string digits = printed_digits(value);
    std::string words = std::string("The paper's ") + value.symbol + " (" + value.where + "): its closed form " +
                        value.closed_form + " is in " + enclosure_words(closed) + ", which " +
                        (vs_closed == "agree" ? "meets" : "is disjoint from") + " the certified " + value.symbol +
                        "; its printed " + value.printed + " " +
                        reading_words(digits, std::string("the certified ") + value.symbol, vs_printed.first, vs_printed.second);
    if (closed_vs_printed)
        words += ", and " + reading_words(digits, "the closed form", closed_vs_printed->first, closed_vs_printed->second);
    words += ".";
    const bool printed_wrong = vs_printed.first == "disagree" && vs_printed.second == "disagree";
    if (vs_closed == "disagree" && printed_wrong)
        words += std::string(" So the paper's ") + value.symbol + " is wrong twice: neither its closed form nor its printed "
                 "value is the certified " + value.symbol + ".";
    return words;
}

// The three families' densities with their slopes at p = 1, from the proof's cases (the
// smallest roots of C0 and C1 replayed, O0 evaluated), each checked against claim.data.
struct SphereSlopes {
    std::vector<ValueAndSlope> cubic;  // C0, C1
    ValueAndSlope o0;
    std::vector<Real> stated;  // the stated slopes of C0, C1 and O0
};

// The cases of proof.cases replayed at p = 1, each family's stated values checked as it comes.
SphereSlopes replay_slopes(Context& context, const Json& data, const Json& proof, const Real& p) {
    const ValueAndSlope t = halving_shift(p);
    const ValueAndSlope volume = superball_volume_with_slope(p);
    const Json& cases = context.member(proof, "cases", "proof");
    if (!cases.is_array()) context.malformed("proof.cases", "expected an array");
    context.require(cases.size() == 3, "proof.cases", "expected three cases: the roots of C0 and C1, and O0");
    std::vector<ValueAndSlope> slopes;
    std::vector<Real> stated_slopes;
    for (int k = 0; k < 2; ++k) {
        const std::string family = k == 0 ? "C0" : "C1", path = "proof.cases[" + std::to_string(k) + "]";
        if (context.string_at(cases[k], "kind", path) != "smallest-root") context.malformed(path + ".kind", "expected smallest-root");
        context.require(context.string_at(cases[k], "family", path) == family, path + ".family", "expected " + family);
        const CubicEquation equation{k == 1, p};
        const Real s = replay_smallest_root(context, equation, cases[k], path);
        context.current_step = "claim.data." + family;
        const ValueAndSlope root = cubic_root_with_slope(equation, s);
        const ValueAndSlope phi = density_with_slope(volume, cubic_abs_determinant(k == 1, root, t));
        stated_slopes.push_back(check_family(context, data, family, "s", root, phi));
        slopes.push_back(phi);
    }
    if (context.string_at(cases[2], "kind", "proof.cases[2]") != "evaluation") context.malformed("proof.cases[2].kind", "expected evaluation");
    context.require(context.string_at(cases[2], "family", "proof.cases[2]") == "O0", "proof.cases[2].family", "expected O0");
    context.current_step = "claim.data.O0";
    const ValueAndSlope c = octahedral_height_with_slope(p);
    const ValueAndSlope o0 = density_with_slope(volume, octahedral_abs_determinant(c));
    stated_slopes.push_back(check_family(context, data, "O0", "c", c, o0));
    return {slopes, o0, stated_slopes};
}

// The paper's closed forms (literature.hpp) and printed values (the table's, not the file's)
// compared with the certified a_minus and a_plus, every stated verdict checked. Returns the
// sentence's words on them.
std::string check_paper_slopes(Context& context, const Json& data, const Real& minus_slope, const Real& plus_slope) {
    const mpfr_prec_t precision = context.precision();
    context.current_step = "claim.data.paper";
    const PrintedValue& paper_minus_value = printed_value(Printed::a_minus);
    const PrintedValue& paper_plus_value = printed_value(Printed::a_plus);
    const Real closed_minus = slope_closed_form(Printed::a_minus, precision);
    const Real closed_plus = slope_closed_form(Printed::a_plus, precision);
    const Json& paper = context.member(data, "paper", "claim.data");
    const Json& paper_minus = context.member(paper, "a_minus", "claim.data.paper");
    const Json& paper_plus = context.member(paper, "a_plus", "claim.data.paper");
    const Real stated_closed_minus = proved_enclosure(context, context.member(paper_minus, "closed_form", "claim.data.paper.a_minus"),
                                                      "claim.data.paper.a_minus.closed_form", closed_minus);
    const Real stated_closed_plus = proved_enclosure(context, context.member(paper_plus, "closed_form", "claim.data.paper.a_plus"),
                                                     "claim.data.paper.a_plus.closed_form", closed_plus);
    const std::string minus_vs_closed =
        check_overlap_verdict(context, paper_minus, "certified_vs_closed_form", minus_slope, closed_minus, "claim.data.paper.a_minus");
    const std::string plus_vs_closed = check_overlap_verdict(context, paper_plus, "certified_vs_closed_form", plus_slope,
                                                             closed_plus, "claim.data.paper.a_plus");
    const std::string minus_digits = printed_at(context, paper_minus, paper_minus_value, "claim.data.paper.a_minus");
    const std::string plus_digits = printed_at(context, paper_plus, paper_plus_value, "claim.data.paper.a_plus");
    const auto minus_printed = check_printed(context, minus_digits, context.member(paper_minus, "certified_vs_printed", "claim.data.paper.a_minus"),
                                             minus_slope, "claim.data.paper.a_minus.certified_vs_printed");
    const auto plus_printed = check_printed(context, plus_digits, context.member(paper_plus, "certified_vs_printed", "claim.data.paper.a_plus"),
                                            plus_slope, "claim.data.paper.a_plus.certified_vs_printed");
    const auto closed_plus_printed =
        check_printed(context, plus_digits, context.member(paper_plus, "closed_form_vs_printed", "claim.data.paper.a_plus"),
                      closed_plus, "claim.data.paper.a_plus.closed_form_vs_printed");
    return paper_words(paper_minus_value, stated_closed_minus, minus_vs_closed, minus_printed, nullptr) + " " +
           paper_words(paper_plus_value, stated_closed_plus, plus_vs_closed, plus_printed, &closed_plus_printed);
}

std::string check_sphere_slopes(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    context.require(context.rational_at(inputs, "p", "inputs") == 1, "inputs.p", "the slopes are claimed at p = 1");
    context.require(context.rational_at(data, "p", "claim.data") == 1, "claim.data.p", "the slopes are claimed at p = 1");
    const mpfr_prec_t precision = context.precision();
    context.current_step = "claim.data";
    const std::string identity = determinant_identity_failure(precision);
    context.require(identity.empty(), "claim.data", "closed-form determinant disagrees with the basis: " + identity);
    const Real p = integer(1, precision);

    const Json& proof = context.member(document, "proof", "");
    if (context.string_at(proof, "kind", "proof") != "all") context.malformed("proof.kind", "expected \"all\"");
    const SphereSlopes slopes = replay_slopes(context, data, proof, p);

    // a_minus is O0's slope; a_plus the larger cubic slope (decided, not assumed).
    const Json& minus = context.member(data, "a_minus", "claim.data");
    context.require(context.string_at(minus, "family", "claim.data.a_minus") == "O0", "claim.data.a_minus.family",
                    "a_minus is the slope of O0");
    const Real stated_minus =
        proved_enclosure(context, context.member(minus, "value", "claim.data.a_minus"), "claim.data.a_minus.value", slopes.o0.slope);
    const Json& plus = context.member(data, "a_plus", "claim.data");
    const std::string plus_family = context.string_at(plus, "family", "claim.data.a_plus");
    const int larger = plus_family == "C0" ? 0 : plus_family == "C1" ? 1 : -1;
    context.require(larger >= 0 && less(slopes.cubic[1 - larger].slope, slopes.cubic[larger].slope), "claim.data.a_plus.family",
                    "the family named is not proved to have the larger cubic slope");
    const Real stated_plus = proved_enclosure(context, context.member(plus, "value", "claim.data.a_plus"),
                                              "claim.data.a_plus.value", slopes.cubic[larger].slope);
    const std::string paper = check_paper_slopes(context, data, slopes.o0.slope, slopes.cubic[larger].slope);

    // The sentence: the stated enclosures and verdicts, each checked above.
    return "At the sphere point p = 1 the slopes of phi = V_sb(p) / |det B| of the lattices of " + std::string(paper_citation) +
           " are: phi_C0'(1) in " + enclosure_words(slopes.stated[0]) + ", phi_C1'(1) in " + enclosure_words(slopes.stated[1]) +
           " (right of p = 1), phi_O0'(1) in " + enclosure_words(slopes.stated[2]) + " (left of p = 1); a_minus = phi_O0'(1) in " +
           enclosure_words(stated_minus) + " and a_plus = phi_" + plus_family + "'(1) in " + enclosure_words(stated_plus) +
           ", the larger cubic slope (both cubic lattices are the FCC lattice at p = 1, so the one with the larger phi just "
           "right of p = 1 is the one with the larger slope). " + paper;
}

const ClaimKindRegistration registration("sphere-slopes", check_sphere_slopes);

}  // namespace

}  // namespace superpack_checker
