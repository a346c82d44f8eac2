// Two claim kinds about the packing verdict of a family lattice (NOTES.md 8.4):
//  - "family-lattice-check" (`superpack check-lattice --family F --p P --certificate FILE`):
//    at one exact p, the family's lattice is a packing with N contacts, or overlaps (witness);
//  - "audit" (`superpack audit --family F --certificate FILE`): pieces [lo, hi] of p with
//    exact rational ends covering a range, each with a verdict valid for every p of the piece
//    (undecided pieces listed with their reason; they prove nothing). O1 pieces whose audit
//    refuted the packing only at the piece's midpoint are "overlapping_at_point" (that one p).
// The proofs embed the family's parameter proof (family_parameter_proof) and the enumeration
// bound with the contact vectors; the checker redoes the enumeration on its own basis.
#pragma once
#include "superpack/problems/families/audit.hpp"
#include "superpack/cert/certificate.hpp"

namespace superpack {

// Throws std::runtime_error for an undecided check or an uncertified family (no proof, no file).
template <class Field>
Json family_lattice_check_certificate(const FamilyLattice<typename Field::Interval>& lattice,
                                      const LatticeCheck<typename Field::Interval>& check, const Rational& p,
                                      const Field& field, long digits);

// Throws std::runtime_error when no piece is decided (nothing would be proved), and
// InputError for the O1 second-root branch or an O1 range not starting at p = 1/2 (the
// branch is identified by continuation from Minkowski's lattice at p = 1/2).
Json audit_certificate(const AuditResult& result);

// How many pieces prove something (packing, overlapping, or overlapping_at_point), given an
// audit certificate or its claim data.
std::size_t decided_pieces(const Json& certificate);

}  // namespace superpack
