// The lattice families, one entry each: everything superpack says about a family apart from
// its formulas (families.hpp) and its certificate's parameter proof (a row of the table in
// src/cert/family_certificate.cpp, the layer above). Commands, the report, `best` and the
// audit read a family through its entry, so adding a family is its enum value, its entry in
// family_registry.cpp, its declaration in src/problems/families/family_enclosure.hpp, that
// row, and its own files (equations, src/problems/families/<family>.cpp, its parameter proof).
#pragma once
#include <string>
#include <vector>

#include "superpack/problems/families/audit.hpp"

namespace superpack {

// Whether an exact p lies in a family's claimed domain. Refused: it could not be decided (S6
// next to its irrational end p*_o), which no command treats as inside.
enum class [[nodiscard]] DomainStatus { inside, outside, refused };

struct [[nodiscard]] DomainMembership {
    DomainStatus status = DomainStatus::inside;
    std::string reason;  // why p is not inside, in the words of the error a command prints
    bool inside() const { return status == DomainStatus::inside; }
};

// The claimed domain on exact p, the reason left to family_domain (outside_reason).
inline DomainMembership domain_if(bool inside) { return {inside ? DomainStatus::inside : DomainStatus::outside, {}}; }

// A family's enclosure at p (an interval: a point for one p, a piece for the audit), for each
// interval type. The family argument tells C0 from C1, which share one enclosure.
template <class I>
using FamilyEnclosure = FamilyLattice<I> (*)(Family family, const I& p);

struct FamilyDefinition {
    Family family;
    const char* name;  // as typed after --family and printed
    std::string source;  // where the family is defined: the paper and its equations
    const char* domain_text;  // the claimed domain in words
    DomainMembership (*domain)(const Rational& p);
    // Run by the report, `best` and the audit, which cover the convex families (p >= 1/2);
    // the insertion (0 < p <= 1/2) only by its name and in `best`.
    bool convex;
    // The coefficient triples (one per +-pair) whose norm is 2 identically by the family's
    // contact equations (NOTES.md section 5), and the contacts the paper claims (v and -v).
    std::vector<Coefficients> contact_triples;
    int claimed_contacts;
    FamilyEnclosure<DInterval> enclose_double;
    FamilyEnclosure<Ball> enclose_ball;
    // The insertion's basis: exact, the same for every p, checked with the exact p (the
    // star-body test below 1/2); no certificate kind of its own. Null for the others.
    Basis<Rational> (*exact_basis)();
    // S6: its contact pairs define it, so its certificates state them.
    bool defined_by_contact_pairs;
    // The audit: the claimed range (null when the family is not audited, why in not_audited),
    // the pieces, and where O1's and D14's continuation starts at p = 1/2 (empty: each piece
    // is enclosed on its own, or S6's chain from its point proof at 9/10).
    AuditRange (*audit_range)();
    const char* not_audited;
    AuditSettings audit_settings;
    std::vector<double> continuation_start;
    // O1 only: where the continuation of its second root (audit --branch second-root) starts.
    std::vector<double> second_root_start;
};

// Every family, in the order of the tables (C0, C1, O0, O1, D14, S6, minkowski-insertion).
const std::vector<FamilyDefinition>& family_registry();
const FamilyDefinition& family_definition(Family family);

// The domain of `family` at exact p, with the reason when p is not inside (also p > 10^300,
// beyond every family: the floating-point guesses need 2p to be a finite binary64 number).
DomainMembership family_domain(Family family, const Rational& p);

inline FamilyEnclosure<DInterval> enclosure_for(const FamilyDefinition& definition, const DInterval&) {
    return definition.enclose_double;
}
inline FamilyEnclosure<Ball> enclosure_for(const FamilyDefinition& definition, const Ball&) {
    return definition.enclose_ball;
}

// p*_o = ln3/ln4 is irrational: the audits cut their ranges at this rational bracket of it,
// checked in interval arithmetic on first use.
const Rational& octahedral_crossover_below();
const Rational& octahedral_crossover_above();

}  // namespace superpack
