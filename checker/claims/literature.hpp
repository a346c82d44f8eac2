// The literature a claim is compared with, in one table in the checker's own source: each
// printed value with its quantity, the value exactly as printed, the closed form printed beside
// it and where it is printed; the paper's claim that O1 packs; and where each family is defined
// (D14 in Dostert and Vallentin 2020).
// A certificate carries none of this as trusted input: a printed value named in a certificate's
// data must be this table's (claim_sphere_slopes.cpp), and the claim sentences quote the table.
//
// The paper: Y. Jiao, F. H. Stillinger and S. Torquato, Optimal packings of superballs, Phys.
// Rev. E 79, 041309 (2009). Equations are numbered as printed, one sequence from Eq. (1) (the
// superball, Sec. I): Sec. III.A (C0) holds Eqs. (2)-(6), Sec. III.B (C1) Eqs. (7)-(9), Sec. IV.A
// (O0) Eqs. (10)-(13), Sec. IV.B (O1) Eqs. (14)-(17).
#pragma once
#include <string>

#include "checker/core/real.hpp"

namespace superpack_checker {

// "Jiao, Stillinger and Torquato, Phys. Rev. E 79, 041309 (2009)", as the sentences cite it.
extern const char* const paper_citation;
// The source of the D14 family: M. Dostert and F. Vallentin, New dense superball packings in
// three dimensions, Adv. Geom. 20 (2020) 473-482 (arXiv:1806.10878), Theorem 4.2.
extern const char* const dostert_vallentin_citation;

enum class Printed { p_star_c, phi_star_c, p_star_o, phi_star_o, a_plus, a_minus };

struct PrintedValue {
    const char* symbol;       // as the sentences name it: "p*_c"
    const char* quantity;     // what it is
    const char* printed;      // exactly as printed: "1.1509..."
    const char* closed_form;  // the closed form printed with it, or ""
    const char* where;        // equation and section
};

const PrintedValue& printed_value(Printed which);
// The printed digits without the ellipsis: "1.1509".
std::string printed_digits(const PrintedValue& value);

// A value printed as "d..." read two ways: truncated (x lies between d and d plus one unit of
// its last place, away from zero) or rounded (within half a unit of d). "agree": x is strictly
// inside the reading; "disagree": strictly outside; else "undecided".
std::string compare_with_printed(const Real& x, const std::string& digits, bool truncated);
// The predicate on a printed value "digits...", from the two verdicts: "is p*_c rounded to 4
// decimals, not truncated", where `what` names the value compared with ("p*_c").
std::string reading_words(const std::string& digits, const std::string& what, const std::string& as_truncated,
                          const std::string& as_rounded);

// "p*_c = 1.1509... (<where>) is p*_c rounded to 4 decimals, not truncated": the printed value
// read against x, an enclosure of the true value (a verdict about x is one about the value).
std::string printed_value_words(Printed which, const Real& x);

// The printed closed forms of a_plus and a_minus, -(pi/(12 sqrt2)) [A + 4 psi(1/2) + 2 psi(3/2) -
// 6 psi(5/2)] with A = 24 + ln 8 (a_plus) and ln 64 + 8 (a_minus), enclosed at `precision`.
Real slope_closed_form(Printed which, mpfr_prec_t precision);

// The paper's claim that the O1 lattice is a packing on (1/2, p*_o), and where it is made.
struct PrintedClaim {
    const char* statement;
    const char* where;
};
extern const PrintedClaim o1_packs;
// " This refutes the paper's statement that <statement> (<where>)."
std::string refutation_words(const PrintedClaim& claim);

// "V_sb(p) the volume of the superball, Eq. (5) of Sec. III.A".
extern const char* const volume_words;

// "the C0 lattice of <paper> (Sec. III.A: basis Eq. (2), s the smallest positive root of Eq. (3), ...)".
std::string lattice_words(const std::string& family);

}  // namespace superpack_checker
