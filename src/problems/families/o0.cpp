// The enclosure of O0 (JST 2009, Eqs. 5-7) at p, the family's entry in the registry
// (family_registry.hpp); its equations are in families.hpp.
#include "family_enclosure.hpp"

namespace superpack {

template <class I>
FamilyLattice<I> enclose_o0(Family family, const I& p) {
    FamilyLattice<I> lattice{family};
    lattice.parameters = {{"c", octahedral_height(p)}};
    finish(lattice, p, o0_basis(p));
    return lattice;
}

template FamilyLattice<DInterval> enclose_o0(Family, const DInterval&);
template FamilyLattice<Ball> enclose_o0(Family, const Ball&);

}  // namespace superpack
