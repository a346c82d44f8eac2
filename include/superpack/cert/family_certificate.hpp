// The certificate of claim kind "family-lattice": phi = V_sb / |det B| of one family (C0, C1,
// O0, O1) at one exact p, with the proof that the contact equations were solved as the paper
// asks (Newton box and root-free [0, s) for C0/C1; the Krawczyk partition of the (q, s) box for
// O1; the partition of the (x, y, z) box for D14; the Krawczyk leaf of the KKT point for S6), and
// the lattice check (packing, overlapping or undecided) that decides whether phi is a
// packing density.
#pragma once
#include <optional>

#include "superpack/cert/certificate.hpp"
#include "superpack/problems/families/family_lattice_check.hpp"

namespace superpack {

// The proof that fixes the family's parameters at p (a point, or an interval of p for which
// the lattice was certified by enclose_family_at): the proof tree of a family-lattice
// certificate, which other claim kinds embed (family-lattice-check, audit).
// Throws std::runtime_error unless lattice.status is certified.
template <class I>
Json family_parameter_proof(const FamilyLattice<I>& lattice, const I& p);

// Throws InputError for a family outside its domain at p and for the insertion, which has no
// family claim (check-lattice certifies its exact basis instead), so that a command refuses
// --certificate before computing. Below p = 1/2 an exact basis has the star-lattice-check kind.
void require_certificate_kind(const Rational& p, std::optional<Family> family);

// What a claim states of the family's definition beside its name: for S6 {"contact_pairs": the
// six triples}, which the checker compares with its own; an empty object for the others, whose
// equations the name fixes.
Json family_definition_json(Family family);

// A lattice verdict as a claim states it: {"verdict": "packing", "contacts", "contact_vectors"},
// {"verdict": "overlapping", "witness": {"coefficients", "norm"}} or {"verdict": "undecided"};
// and its proof: the enumeration {"kind", "coefficient_bound", "contacts"} of a packing (the
// checker enumerates the box on its own basis), null otherwise (a witness is its own proof).
template <class I>
Json lattice_verdict_json(const LatticeCheck<I>& check);
template <class I>
Json lattice_enumeration_json(const LatticeCheck<I>& check);

// Throws std::runtime_error unless lattice.status is certified (only proofs are certified).
template <class Field>
Json family_certificate(const FamilyLattice<typename Field::Interval>& lattice, const Rational& p,
                        const Field& field, long digits);

}  // namespace superpack
