#include "checker/claims/literature.hpp"

#include <stdexcept>

#include "checker/claims/family_parameters.hpp"
#include "checker/formulas/equations_crossover.hpp"

namespace superpack_checker {

const char* const paper_citation = "Jiao, Stillinger and Torquato, Phys. Rev. E 79, 041309 (2009)";
const char* const dostert_vallentin_citation =
    "Dostert and Vallentin, New dense superball packings in three dimensions, Adv. Geom. 20 (2020) 473-482";

namespace {

// The table. Values and closed forms are copied from the paper as printed (its digits, its
// ellipsis); "where" is the first place that prints them, then the others.
const PrintedValue table[] = {
    {"p*_c", "the p where the C0 and C1 lattices have the same density", "1.1509...", "",
     "Sec. III.A; also the abstract, Sec. I and the caption of Fig. 5"},
    {"phi*_c", "the density of the C0 and C1 lattices at p*_c", "0.7596...", "", "Sec. III.A"},
    {"p*_o", "the root of Eq. (11), where the O0 and O1 lattices meet", "0.7924...", "ln3/ln4",
     "Sec. IV.A, after Eq. (11); also the abstract and Sec. I"},
    {"phi*_o", "the density of the O0 and O1 lattices at p*_o", "0.7959...", "", "Sec. IV.A, after Eq. (11); also Sec. IV.B"},
    {"a_plus", "the right slope of the maximal density at p = 1", "0.3555...",
     "-(pi/(12 sqrt2)) [24 + ln 8 + 4 psi(1/2) + 2 psi(3/2) - 6 psi(5/2)]", "Eq. (6), Sec. III.A"},
    {"a_minus", "the left slope of the maximal density at p = 1", "-0.02941...",
     "-(pi/(12 sqrt2)) [ln 64 + 8 + 4 psi(1/2) + 2 psi(3/2) - 6 psi(5/2)]", "Eq. (13), Sec. IV.A"},
};

// The decimal d of "d..." as the interval its reading allows.
std::pair<mpq_class, mpq_class> reading(const std::string& digits, bool truncated) {
    const std::size_t point = digits.find('.');
    std::string integer_digits = digits;
    mpz_class scale = 1;
    if (point != std::string::npos) {
        integer_digits.erase(point, 1);
        for (std::size_t k = point + 1; k < digits.size(); ++k) scale *= 10;
    }
    mpq_class value(mpz_class(integer_digits, 10), scale);
    value.canonicalize();
    const mpq_class unit(1, scale);
    if (!truncated) return {value - unit / 2, value + unit / 2};
    if (digits[0] == '-') return {value - unit, value};
    return {value, value + unit};
}

}  // namespace

const PrintedValue& printed_value(Printed which) { return table[static_cast<int>(which)]; }

std::string printed_digits(const PrintedValue& value) {
    const std::string printed = value.printed;
    return printed.substr(0, printed.find("..."));
}

std::string compare_with_printed(const Real& x, const std::string& digits, bool truncated) {
    const auto [lo, hi] = reading(digits, truncated);
    const Real low = rational(lo, x.precision()), high = rational(hi, x.precision());
    if (less(low, x) && less(x, high)) return "agree";
    if (less(x, low) || less(high, x)) return "disagree";
    return "undecided";
}

std::string reading_words(const std::string& digits, const std::string& what, const std::string& as_truncated,
                          const std::string& as_rounded) {
    const std::size_t point = digits.find('.');
    const std::string places = std::to_string(point == std::string::npos ? 0 : digits.size() - point - 1) + " decimals";
    if (as_truncated == "agree" && as_rounded == "agree")
        return "is " + what + " truncated and rounded to " + places;
    if (as_truncated == "agree" && as_rounded == "disagree")
        return "is " + what + " truncated to " + places + ", not rounded";
    if (as_truncated == "disagree" && as_rounded == "agree")
        return "is " + what + " rounded to " + places + ", not truncated";
    if (as_truncated == "disagree" && as_rounded == "disagree")
        return "is neither " + what + " truncated nor rounded to " + places;
    return "compares with " + what + " truncated to " + places + ": " + as_truncated + "; rounded: " + as_rounded;
}

std::string printed_value_words(Printed which, const Real& x) {
    const PrintedValue& value = printed_value(which);
    const std::string digits = printed_digits(value);
    return std::string(value.symbol) + " = " + value.printed + " (" + value.where + ") " +
           reading_words(digits, value.symbol, compare_with_printed(x, digits, true), compare_with_printed(x, digits, false));
}

Real slope_closed_form(Printed which, mpfr_prec_t precision) {
    if (which != Printed::a_plus && which != Printed::a_minus) throw std::logic_error("no closed form of a slope");
    const Real factor = -(pi(precision) / (12 * sqrt(integer(2, precision))));
    const Real psis = 4 * digamma(rational(mpq_class(1, 2), precision)) + 2 * digamma(rational(mpq_class(3, 2), precision)) -
                      6 * digamma(rational(mpq_class(5, 2), precision));
    const Real constant = which == Printed::a_plus ? integer(24, precision) + log(integer(8, precision))
                                                   : log(integer(64, precision)) + integer(8, precision);
    return factor * (constant + psis);
}

const PrintedClaim o1_packs{"the O1 lattice gives the densest known packings, each superball with 12 contacting "
                            "neighbors, for 0.5 < p < p*_o",
                            "Sec. IV.B, after Eq. (16)"};

std::string refutation_words(const PrintedClaim& claim) {
    return std::string(" This refutes the paper's statement that ") + claim.statement + " (" + claim.where + ").";
}

const char* const volume_words = "V_sb(p) the volume of the superball, Eq. (5) of Sec. III.A";

std::string lattice_words(const std::string& family) {
    const std::string of = std::string("of ") + paper_citation + " ";
    if (family == "C0")
        return "the C0 lattice " + of + "(Sec. III.A: basis Eq. (2), s the smallest positive root of Eq. (3), "
               "(s + t)^(2p) + s^(2p) + 2^(-2p) - 1 = 0 with t = 2^(-1/(2p)))";
    if (family == "C1")
        return "the C1 lattice " + of + "(Sec. III.B: basis Eq. (7), s the smallest positive root of Eq. (8), "
               "(s + t)^(2p) + 2 s^(2p) - 1 = 0 with t = 2^(-1/(2p)))";
    if (family == "O0") return "the O0 lattice " + of + "(Sec. IV.A: basis Eq. (10), c = (1 - 2^(1-2p))^(1/(2p)))";
    if (family == "O1")
        return "the O1 lattice " + of + "(Sec. IV.B: basis Eq. (15), (q, s) the root of Eq. (16), 2|q|^(2p) + |s|^(2p) = 1 and "
               "|l+q|^(2p) + |s-l|^(2p) + |l-q|^(2p) = 1 with l = 3^(-1/(2p)), with q >= 0 and the larger s: the "
               "Minkowski branch)";
    if (family == "D14")
        return std::string("the D14 lattice of ") + dostert_vallentin_citation +
               " (Theorem 4.2, their exponent 2p: basis 2(-x, y, z), 2(z, -x, y), 2(y, z, -x), (x, y, z) the root of "
               "|x|^(2p) + |y|^(2p) + |z|^(2p) = 1, |x-y|^(2p) + |z-x|^(2p) + |y+z|^(2p) = 1 and 3|-x+y+z|^(2p) = 1 with "
               "x, y, z > 0 and y < z)";
    if (family == "S6") {
        std::string triples;
        for (const Triple& c : s6_triples()) triples += (triples.empty() ? "" : ", ") + triple_text(c);
        return "the S6 lattice, superpack's own family (issue 12; NOTES.md 4.2), not a published one: the basis B of "
               "the unique KKT point (B, mu) in the certified box of min det B subject to ||c B||_(2p) = 2 for Minkowski's "
               "six pairs (configuration A3) c = " + triples;
    }
    throw std::logic_error("unknown family " + family);
}

}  // namespace superpack_checker
