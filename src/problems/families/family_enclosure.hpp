// What the enclosures of the families share (src/problems/families/, one file per family):
// the last step every certified lattice takes, and p*_o. Each family's enclosure is a
// template over the interval type, declared here and instantiated for DInterval and Ball in
// its own file, so that the registry (family_registry.cpp) can point at it.
#pragma once
#include "superpack/problems/families/families.hpp"

namespace superpack {

// The volume, determinant and phi of a certified basis, and the proved status.
template <class I>
void finish(FamilyLattice<I>& lattice, const I& p, Basis<I> basis) {
    lattice.volume = enclose_ball_volume(p, 3);
    lattice.determinant = determinant(basis);
    lattice.phi = *lattice.volume / abs(*lattice.determinant);
    lattice.basis = std::move(basis);
    lattice.status = Outcome::proved;
}

// p*_o = ln 3 / ln 4, where the Minkowski branch of Eq. 12 reaches q = 0 (NOTES.md).
template <class I>
I octahedral_crossover(const I& like) {
    const auto field = field_of(like);
    return log(field.integer(3)) / log(field.integer(4));
}

// The enclosure of each family at p (an interval: a point for one p, a piece for the audit).
// The family argument tells C0 from C1, which share one enclosure.
template <class I> FamilyLattice<I> enclose_cubic(Family family, const I& p);
template <class I> FamilyLattice<I> enclose_o0(Family family, const I& p);
template <class I> FamilyLattice<I> enclose_o1(Family family, const I& p);
template <class I> FamilyLattice<I> enclose_d14(Family family, const I& p);
template <class I> FamilyLattice<I> enclose_s6(Family family, const I& p);
template <class I> FamilyLattice<I> enclose_insertion(Family family, const I& p);

}  // namespace superpack
