// The second claim kind, "lattice-check" (written by `superpack check-lattice --basis ...
// --certificate FILE`): the lattice with an exact basis is a packing of the superball at an
// exact p with N contacts, or is not one (a witness vector of norm < 2). NOTES.md section 8.
#pragma once
#include "superpack/cert/certificate.hpp"
#include "superpack/geometry/lattice.hpp"

namespace superpack {

// The basis rows as exact texts, "3/2".
Json rational_basis_json(const Basis<Rational>& basis);

// The part of an enumeration's proof the checker replays first (NOTES.md 5.2 and 5.6): {kind
// "enumeration", reduction, coefficient_bound, bound_data {determinant, cross_norms}} of the
// reduced basis the check enumerated (the given one when the check has no reduction).
template <class Field>
Json enumeration_proof_json(const LatticeCheck<typename Field::Interval>& check, const Basis<Rational>& basis,
                            const Field& field);

// Builds the certificate of a decided check of an exact basis at an exact p (the check must
// come from check_exact_lattice(basis, p, field)). Throws std::runtime_error for an undecided
// check: no certificate without a proof.
template <class Field>
Json lattice_certificate(const LatticeCheck<typename Field::Interval>& check, const Basis<Rational>& basis,
                         const Rational& p, const Field& field, long digits);

}  // namespace superpack
