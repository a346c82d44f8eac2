// The packing verdict of a family lattice, replayed from the family's parameter enclosures
// (valid for every p of an interval): the checker builds its own interval basis from the exact
// linear forms of equations_audit.hpp, bounds the coefficients of every vector of 2p-norm <= 2
// (Cramer and Hoelder, NOTES.md 5.2), enumerates that box itself and decides every triple:
// a coordinate certainly beyond 2, a norm certainly > 2, a contact by a unit equation of the
// family (identically norm 2), or else the packing claim is rejected. Shared by the claim
// kinds family-lattice-check and audit.
#pragma once
#include <optional>
#include <string>

#include "checker/claims/family_parameters.hpp"
#include "checker/formulas/equations_audit.hpp"
#include "checker/formulas/triple.hpp"

namespace superpack_checker {

// What a verified verdict says, for the claim sentence: the contact count of a packing, or the
// witness and its stated norm enclosure (proved to contain the checker's norm).
struct FamilyVerdict {
    bool packing = false;
    long contacts = 0;
    Triple witness{};
    std::optional<Real> witness_norm;
};

// `verdict` is "packing" or "overlapping" (the caller reads it from `stated`; an audit piece
// overlapping at a point is checked as overlapping there); `stated` holds {"contacts",
// "contact_vectors"} (packing) or {"witness": {"coefficients", "norm"}} (overlapping);
// `enumeration` is the proof's {"kind": "enumeration", "coefficient_bound", "contacts":
// [{"coefficients"}]} for a packing and null for an overlap (the witness is its own proof).
// p must be >= 1/2 throughout (the caller checks it on exact rationals).
FamilyVerdict check_family_verdict(Context& context, const FamilyForms& forms, const NamedReals& symbols, const Real& p,
                                   const std::string& verdict, const Json& stated, const std::string& stated_path,
                                   const Json& enumeration, const std::string& enumeration_path);

// "is a packing of the superball ... with 12 contacts (...)" or "is not a packing: the lattice
// vector (1, -1, -1) has 2p-norm in [...] < 2".
std::string verdict_words(const FamilyVerdict& verdict);

}  // namespace superpack_checker
