// Claim kind "star-lattice-check" (written by `superpack check-lattice --basis ... --certificate
// FILE` and `best --certificate FILE` below p = 1/2): the lattice with an exact basis is a packing
// of the concave superball at an exact p < 1/2 (every candidate's translate proved disjoint from K
// by the closed form of geometry/star_cases.hpp), or is not one (a rational point inside K and
// K + v for a lattice vector v). NOTES.md 13.5.
#pragma once
#include "superpack/cert/certificate.hpp"
#include "superpack/geometry/lattice.hpp"

namespace superpack {

// The check must come from check_exact_lattice(basis, p, field) with p < 1/2. Throws
// std::runtime_error for an undecided check, for a candidate the closed form leaves undecided
// (decided by the box cover alone, which the checker does not replay) and for a witness point
// that is no longer inside both bodies once rounded to a rational point.
template <class Field>
Json star_lattice_certificate(const LatticeCheck<typename Field::Interval>& check, const Basis<Rational>& basis,
                              const Rational& p, const Field& field, long digits);

// The certificate of a decided check of an exact basis at any p: star-lattice-check below 1/2,
// lattice-check (cert/lattice_certificate.hpp) from 1/2 on.
template <class Field>
Json exact_lattice_certificate(const LatticeCheck<typename Field::Interval>& check, const Basis<Rational>& basis,
                               const Rational& p, const Field& field, long digits);

}  // namespace superpack
