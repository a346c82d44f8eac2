// The lattices of the families as packings: which lattice vectors are contacts by the
// family's own contact equations (NOTES.md section 5, "Contacts of the families"), and the
// lattice check of a certified family lattice.
#pragma once
#include <vector>

#include "superpack/geometry/lattice.hpp"
#include "superpack/problems/families/families.hpp"

namespace superpack {

// Families: the coefficient triples (one per +-pair) whose norm is 2 identically by the family's
// contact equations (NOTES.md section 5, "Contacts of the families").
std::vector<Coefficients> family_contact_triples(Family family);
// The number of contacts the paper claims for the family (counting v and -v).
int claimed_contacts(Family family);

// The verdict for a certified family lattice at p (a point or a piece): this is the function
// the report calls. Undecided with the family's message when the lattice is not certified.
template <class I>
LatticeCheck<I> check_family_lattice(const FamilyLattice<I>& lattice, const I& p);
// The same at one exact p: the commands' entry, which also checks the insertion (its exact basis,
// by the star-body test below p = 1/2).
template <class I>
LatticeCheck<I> check_family_lattice(const FamilyLattice<I>& lattice, const Rational& p);

}  // namespace superpack
