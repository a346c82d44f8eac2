#include "superpack/problems/families/family_registry.hpp"

#include <stdexcept>

#include "family_enclosure.hpp"
#include "superpack/problems/families/s6_definition.hpp"

namespace superpack {

namespace {

// p > p*_o = ln3/ln4 for the exact p, decided on enclosures of ln3/ln4 at 64 to 4096 bits (p is
// rational and p*_o is not, so a fine enough enclosure separates them). A p that not even 4096
// bits separate from p*_o is refused with that reason.
DomainMembership above_octahedral_crossover(const Rational& p) {
    for (const long bits : {64L, 256L, 1024L, 4096L}) {
        const BallField field{bits};
        const Ball exact_p = field.rational(p), crossover = octahedral_crossover(exact_p);
        if (certainly_less(crossover, exact_p)) return domain_if(true);
        if (certainly_less(exact_p, crossover)) return domain_if(false);
    }
    return {DomainStatus::refused, "p = " + decimal_or_fraction_text(p) +
                                       " is too close to p*_o = ln3/ln4 to decide p > p*_o with 4096 bits: refused for S6"};
}

const std::string bracket_note = "p*_o = ln3/ln4 is irrational: the piece [792481/10^6, 792482/10^6] brackets it "
                                 "(checked in interval arithmetic) and is audited as one piece";

std::vector<FamilyDefinition> make_registry() {
    const std::string jst = "Jiao, Stillinger & Torquato, Phys. Rev. E 79, 041309 (2009), ";
    // b1, b2, b3, b1 + b2, b2 + b3, b1 + b3, b1 + b2 + b3: Minkowski's seven pairs.
    const std::vector<Coefficients> minkowski_seven{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}};
    const auto cubic_range = [] { return AuditRange{Rational(1), Rational(10), {}, "the claim is p >= 1; audited on [1, 10]"}; };
    return {
        {Family::C0, "C0", jst + "Eqs. 1-3", "p >= 1", [](const Rational& p) { return domain_if(p >= 1); }, true,
         {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, -1}, {1, 0, -1}, {1, 1, -1}}, 12,
         enclose_cubic<DInterval>, enclose_cubic<Ball>, nullptr, false, cubic_range, nullptr, {16, 12}, {}, {}},
        {Family::C1, "C1", jst + "Eqs. 8-10", "p >= 1", [](const Rational& p) { return domain_if(p >= 1); }, true,
         {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, -1, 0}, {1, 0, -1}, {0, 1, -1}}, 12,
         enclose_cubic<DInterval>, enclose_cubic<Ball>, nullptr, false, cubic_range, nullptr, {16, 12}, {}, {}},
        {Family::O0, "O0", jst + "Eqs. 5-7", "1/2 < p <= 1",
         [](const Rational& p) { return domain_if(p > Rational(1, 2) && p <= 1); }, true,
         {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, -1}, {0, 1, -1}, {1, 1, -1}}, 12,
         enclose_o0<DInterval>, enclose_o0<Ball>, nullptr, false,
         [] {
             return AuditRange{octahedral_crossover_below(), Rational(1), {octahedral_crossover_above()},
                               "claimed [p*_o, 1]; " + bracket_note};
         },
         nullptr, {16, 12}, {}, {}},
        // O1's root search (two unknowns) costs grow fast with the width of p: keep pieces ~7e-4
        // and do not bisect (an undecided piece still gets the certified midpoint check). Its
        // branch starts at Minkowski's (q, s) = (1/6, 2/3), its second root's at (5/12, 1/6).
        {Family::O1, "O1", jst + "Eqs. 11-13", "p >= 1/2", [](const Rational& p) { return domain_if(p >= Rational(1, 2)); },
         true, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, -1, 0}, {1, 0, -1}}, 12,
         enclose_o1<DInterval>, enclose_o1<Ball>, nullptr, false,
         [] {
             return AuditRange{Rational(1, 2), octahedral_crossover_above(), {octahedral_crossover_below()},
                               "claimed [1/2, p*_o]; " + bracket_note};
         },
         nullptr, {300, 3}, {1.0 / 6, 2.0 / 3}, {5.0 / 12, 1.0 / 6}},
        // D14 follows its root by continuation from (x, y, z) = (1/3, 1/6, 1/2) (a small
        // Krawczyk box per piece, no search), so the pieces may be wide; they only shrink where
        // the root nears the fold at p*_o.
        {Family::D14, "D14",
         "Dostert & Vallentin, New dense superball packings in three dimensions, Adv. Geom. 20 (2020) 473-482, "
         "Theorem 4.2",
         "1/2 <= p <= 1", [](const Rational& p) { return domain_if(p >= Rational(1, 2) && p <= 1); }, true, minkowski_seven,
         14, enclose_d14<DInterval>, enclose_d14<Ball>, nullptr, false,
         [] {
             return AuditRange{Rational(1, 2), octahedral_crossover_above(), {octahedral_crossover_below()},
                               "Dostert and Vallentin prove (1/2, 0.79] and conjecture [1/2, p*_o]; " + bracket_note};
         },
         nullptr, {32, 12}, {1.0 / 3, 1.0 / 6, 1.0 / 2}, {}},
        // S6: contacts by the constraints n_i = 2 of the KKT system, Minkowski's six pairs. The
        // mean-value Krawczyk proves pieces 1.25e-4 wide near 9/10, not 2.5e-4 (NOTES.md 4.2).
        {Family::S6, "S6",
         "superpack's own family (issue 12): the KKT point of min |det| for Minkowski's six pairs (configuration "
         "A3), NOTES.md 4.2",
         "ln3/ln4 < p < 1",
         [](const Rational& p) { return p < 1 ? above_octahedral_crossover(p) : domain_if(false); }, true,
         s6_contact_triples(), 12, enclose_s6<DInterval>, enclose_s6<Ball>, nullptr, true,
         [] {
             return AuditRange{Rational(89, 100), Rational(91, 100), {},
                               "S6 is defined on (p*_o, 1); the default audits a range about the point proof at p = 9/10 "
                               "that runs in seconds (audit --family S6 --p-range a:b for others; NOTES.md 4.2)"};
         },
         nullptr, {160, 8}, {}, {}},
        // No contact equations: the basis is exact, and the lattice check with the exact p
        // decides its contacts exactly.
        {Family::MinkowskiInsertion, "minkowski-insertion",
         jst + "Sec. IV.C, Eq. 10: the concave superball inside each octahedron of Minkowski's densest lattice "
               "packing of octahedra",
         "0 < p <= 1/2", [](const Rational& p) { return domain_if(p > 0 && p <= Rational(1, 2)); }, false, {}, 12,
         enclose_insertion<DInterval>, enclose_insertion<Ball>, minkowski_octahedron_basis, false, nullptr,
         "audit: minkowski-insertion is not audited yet: its lattice does not depend on p, but the star-body test below "
         "p = 1/2 takes one exact p (check-lattice --family minkowski-insertion --p P decides each p)",
         {16, 12}, {}, {}},
    };
}

}  // namespace

const std::vector<FamilyDefinition>& family_registry() {
    static const std::vector<FamilyDefinition> registry = make_registry();
    return registry;
}

const FamilyDefinition& family_definition(Family family) {
    for (const FamilyDefinition& definition : family_registry())
        if (definition.family == family) return definition;
    throw std::logic_error("a family without its entry in family_registry.cpp");
}

DomainMembership family_domain(Family family, const Rational& p) {
    const FamilyDefinition& definition = family_definition(family);
    static const Rational largest = [] {
        Rational power = 1;
        for (int k = 0; k < 300; ++k) power *= 10;
        return power;
    }();
    // The text of p only for a reason: printing a rational costs more than the test itself.
    const auto p_text = [&p] { return "p = " + decimal_or_fraction_text(p); };
    if (p > largest)
        return {DomainStatus::outside, p_text() + " is beyond the supported p <= 10^300 of " + definition.name +
                                           " (the floating-point guesses need 2p to be a finite binary64 number)"};
    DomainMembership membership = definition.domain(p);
    if (membership.status == DomainStatus::outside && membership.reason.empty())
        membership.reason = p_text() + " is outside the domain of " + definition.name + " (" + definition.domain_text + ")";
    return membership;
}

namespace {

// p*_o = ln 3 / ln 4 lies in (792481/10^6, 792482/10^6); checked once in interval arithmetic.
const std::pair<Rational, Rational>& octahedral_crossover_bracket() {
    static const std::pair<Rational, Rational> bracket = [] {
        const std::pair<Rational, Rational> candidate{Rational(792481, 1000000), Rational(792482, 1000000)};
        const DoubleField field;
        const DInterval crossover = octahedral_crossover(field.integer(1));
        if (!certainly_less(field.rational(candidate.first), crossover) ||
            !certainly_less(crossover, field.rational(candidate.second)))
            throw std::logic_error("the rational bracket of p*_o = ln3/ln4 is wrong");
        return candidate;
    }();
    return bracket;
}

}  // namespace

const Rational& octahedral_crossover_below() { return octahedral_crossover_bracket().first; }
const Rational& octahedral_crossover_above() { return octahedral_crossover_bracket().second; }

}  // namespace superpack
