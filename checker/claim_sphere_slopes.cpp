// Claim kind "sphere-slopes" (written by `superpack slopes --certificate`): the slopes
// dphi/dp at the sphere point p = 1 of C0, C1 (right of 1) and O0 (left of 1), a_minus (O0's),
// a_plus (the larger cubic slope: at p = 1 both cubic densities are pi/sqrt18, so the denser
// cubic family just right of 1 is the one with the larger slope), and the paper's closed forms
// and printed decimals with three-valued verdicts. The checker recomputes every slope by
// implicit differentiation in its own arithmetic (checker/equations_crossover.*).
#include "checker/equations_crossover.hpp"
#include "checker/replay.hpp"
#include "checker/smallest_root.hpp"

namespace superpack_checker {

namespace {

void check_family(Context& context, const Json& data, const std::string& family, const std::string& parameter,
                  const ValueAndSlope& own_parameter, const ValueAndSlope& phi) {
    const std::string path = "claim.data." + family;
    const Json& stated = context.member(data, family, "claim.data");
    check_encloses(context, context.member(stated, parameter, path), path + "." + parameter, own_parameter.value);
    check_encloses(context, context.member(stated, "d" + parameter + "_dp", path), path + ".d" + parameter + "_dp",
                   own_parameter.slope);
    check_encloses(context, context.member(stated, "phi", path), path + ".phi", phi.value);
    check_encloses(context, context.member(stated, "slope", path), path + ".slope", phi.slope);
}

// A decimal "d..." read as truncated (between d and d plus one unit of its last place, away
// from zero) or rounded (within half a unit of d).
std::pair<mpq_class, mpq_class> reading(const std::string& printed, bool truncated) {
    const std::size_t point = printed.find('.');
    std::string digits = printed;
    mpz_class scale = 1;
    if (point != std::string::npos) {
        digits.erase(point, 1);
        for (std::size_t k = point + 1; k < printed.size(); ++k) scale *= 10;
    }
    mpq_class value(mpz_class(digits, 10), scale);
    value.canonicalize();
    const mpq_class unit(1, scale);
    if (!truncated) return {value - unit / 2, value + unit / 2};
    if (printed[0] == '-') return {value - unit, value};
    return {value, value + unit};
}

// agree: x strictly inside (lo, hi); disagree: strictly outside [lo, hi]; else undecided.
std::string classify(const Real& x, const mpq_class& lo, const mpq_class& hi) {
    const Real low = rational(lo, x.precision()), high = rational(hi, x.precision());
    if (less(low, x) && less(x, high)) return "agree";
    if (less(x, low) || less(high, x)) return "disagree";
    return "undecided";
}

// The verdicts {"as_truncated", "as_rounded"} at `path` for x against a printed decimal.
void check_printed(Context& context, const std::string& printed, const Json& verdicts, const Real& x,
                   const std::string& path) {
    for (const auto& [name, truncated] : {std::pair<const char*, bool>{"as_truncated", true}, {"as_rounded", false}}) {
        const std::string stated = context.string_at(verdicts, name, path);
        const auto [lo, hi] = reading(printed, truncated);
        const std::string own = classify(x, lo, hi);
        context.require(stated == "undecided" || stated == own, path + "." + name,
                        "stated \"" + stated + "\", the checker finds \"" + own + "\"");
    }
}

std::string printed_at(Context& context, const Json& node, const std::string& path) {
    const std::string printed = context.string_at(node, "printed", path);
    const bool decimal = !printed.empty() && printed.size() < 40 && printed.find_first_not_of("-0123456789.") == std::string::npos &&
                         printed.find('-', 1) == std::string::npos && printed.find('.') == printed.rfind('.') &&
                         printed.find_first_of("0123456789") != std::string::npos;
    if (!decimal) context.malformed(path + ".printed", "expected a decimal");
    return printed;
}

void check_overlap_verdict(Context& context, const Json& node, const std::string& key, const Real& a, const Real& b,
                           const std::string& path) {
    const std::string stated = context.string_at(node, key, path);
    Real meet(a.precision());
    const std::string own = intersect(meet, a, b) ? "agree" : "disagree";
    context.require(stated == own, path + "." + key, "stated \"" + stated + "\", the checker finds \"" + own + "\"");
}

void check_sphere_slopes(const Json& claim, Context& context) {
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
    const ValueAndSlope t = halving_shift(p);
    const ValueAndSlope volume = superball_volume_with_slope(p);

    const Json& proof = context.member(document, "proof", "");
    if (context.string_at(proof, "kind", "proof") != "all") context.malformed("proof.kind", "expected \"all\"");
    const Json& cases = context.member(proof, "cases", "proof");
    if (!cases.is_array()) context.malformed("proof.cases", "expected an array");
    context.require(cases.size() == 3, "proof.cases", "expected three cases: the roots of C0 and C1, and O0");
    ValueAndSlope slopes[2] = {{p, p}, {p, p}};
    for (int k = 0; k < 2; ++k) {
        const std::string family = k == 0 ? "C0" : "C1", path = "proof.cases[" + std::to_string(k) + "]";
        context.require(context.string_at(cases[k], "family", path) == family, path + ".family", "expected " + family);
        const CubicEquation equation{k == 1, p};
        const Real s = replay_smallest_root(context, equation, cases[k], path);
        context.current_step = "claim.data." + family;
        const ValueAndSlope root = cubic_root_with_slope(equation, s);
        const ValueAndSlope phi = density_with_slope(volume, cubic_abs_determinant(k == 1, root, t));
        check_family(context, data, family, "s", root, phi);
        slopes[k] = phi;
    }
    context.require(context.string_at(cases[2], "family", "proof.cases[2]") == "O0", "proof.cases[2].family", "expected O0");
    context.current_step = "claim.data.O0";
    const ValueAndSlope c = octahedral_height_with_slope(p);
    const ValueAndSlope o0 = density_with_slope(volume, octahedral_abs_determinant(c));
    check_family(context, data, "O0", "c", c, o0);

    // a_minus is O0's slope; a_plus the larger cubic slope (decided, not assumed).
    const Json& minus = context.member(data, "a_minus", "claim.data");
    context.require(context.string_at(minus, "family", "claim.data.a_minus") == "O0", "claim.data.a_minus.family",
                    "a_minus is the slope of O0");
    check_encloses(context, context.member(minus, "value", "claim.data.a_minus"), "claim.data.a_minus.value", o0.slope);
    const Json& plus = context.member(data, "a_plus", "claim.data");
    const std::string plus_family = context.string_at(plus, "family", "claim.data.a_plus");
    const int larger = plus_family == "C0" ? 0 : plus_family == "C1" ? 1 : -1;
    context.require(larger >= 0 && less(slopes[1 - larger].slope, slopes[larger].slope), "claim.data.a_plus.family",
                    "the family named is not proved to have the larger cubic slope");
    check_encloses(context, context.member(plus, "value", "claim.data.a_plus"), "claim.data.a_plus.value",
                   slopes[larger].slope);

    // The paper's closed forms -(pi/(12 sqrt2)) [A + 4 psi(1/2) + 2 psi(3/2) - 6 psi(5/2)],
    // A = ln 64 + 8 (a_minus) and 24 + ln 8 (a_plus).
    context.current_step = "claim.data.paper";
    Real pi(precision), root2(precision);
    mpfi_const_pi(pi.get());
    mpfi_sqrt(root2.get(), integer(2, precision).get());
    const Real factor = -(pi / (12 * root2));
    const Real psis = 4 * digamma(rational(mpq_class(1, 2), precision)) + 2 * digamma(rational(mpq_class(3, 2), precision)) -
                      6 * digamma(rational(mpq_class(5, 2), precision));
    const Real closed_minus = factor * (log(integer(64, precision)) + integer(8, precision) + psis);
    const Real closed_plus = factor * (integer(24, precision) + log(integer(8, precision)) + psis);
    const Json& paper = context.member(data, "paper", "claim.data");
    const Json& paper_minus = context.member(paper, "a_minus", "claim.data.paper");
    const Json& paper_plus = context.member(paper, "a_plus", "claim.data.paper");
    check_encloses(context, context.member(paper_minus, "closed_form", "claim.data.paper.a_minus"),
                   "claim.data.paper.a_minus.closed_form", closed_minus);
    check_encloses(context, context.member(paper_plus, "closed_form", "claim.data.paper.a_plus"),
                   "claim.data.paper.a_plus.closed_form", closed_plus);
    check_overlap_verdict(context, paper_minus, "certified_vs_closed_form", o0.slope, closed_minus, "claim.data.paper.a_minus");
    check_overlap_verdict(context, paper_plus, "certified_vs_closed_form", slopes[larger].slope, closed_plus,
                          "claim.data.paper.a_plus");
    const std::string minus_printed = printed_at(context, paper_minus, "claim.data.paper.a_minus");
    const std::string plus_printed = printed_at(context, paper_plus, "claim.data.paper.a_plus");
    check_printed(context, minus_printed, context.member(paper_minus, "certified_vs_printed", "claim.data.paper.a_minus"),
                  o0.slope, "claim.data.paper.a_minus.certified_vs_printed");
    check_printed(context, plus_printed, context.member(paper_plus, "certified_vs_printed", "claim.data.paper.a_plus"),
                  slopes[larger].slope, "claim.data.paper.a_plus.certified_vs_printed");
    check_printed(context, plus_printed, context.member(paper_plus, "closed_form_vs_printed", "claim.data.paper.a_plus"),
                  closed_plus, "claim.data.paper.a_plus.closed_form_vs_printed");
}

const ClaimKindRegistration registration("sphere-slopes", check_sphere_slopes);

}  // namespace

}  // namespace superpack_checker
