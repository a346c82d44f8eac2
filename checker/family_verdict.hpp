// The packing verdict of a family lattice, replayed from the family's parameter enclosures
// (valid for every p of an interval): the checker builds its own interval basis from the exact
// linear forms of equations_audit.hpp, bounds the coefficients of every vector of 2p-norm <= 2
// (Cramer and Hoelder, NOTES.md 5.2), enumerates that box itself and decides every triple:
// a coordinate certainly beyond 2, a norm certainly > 2, a contact by a unit equation of the
// family (identically norm 2), or else the packing claim is rejected. Shared by the claim
// kinds family-lattice-check and audit.
#pragma once
#include <string>

#include "checker/equations_audit.hpp"
#include "checker/family_parameters.hpp"
#include "checker/triple.hpp"

namespace superpack_checker {

// `stated` is an object {"verdict": "packing" | "overlapping", "contacts", "contact_vectors"
// (packing) | "witness": {"coefficients", "norm"} (overlapping)}; `enumeration` is the proof's
// {"kind": "enumeration", "coefficient_bound", "contacts": [{"coefficients"}]} (packing only).
// p must be >= 1/2 throughout (the caller checks it on exact rationals).
void check_family_verdict(Context& context, const FamilyForms& forms, const NamedReals& symbols, const Real& p,
                          const Json& stated, const std::string& stated_path, const Json& enumeration,
                          const std::string& enumeration_path);

}  // namespace superpack_checker
