// The enclosure of the Minkowski insertion (JST 2009, Sec. IV.C, Eq. 10) at p, the family's
// entry in the registry (family_registry.hpp): Minkowski's exact octahedron lattice.
#include "family_enclosure.hpp"

#include "superpack/geometry/lattice.hpp"

namespace superpack {

template <class I>
FamilyLattice<I> enclose_insertion(Family family, const I& p) {
    FamilyLattice<I> lattice{family};  // no parameters: the basis does not depend on p
    finish(lattice, p, enclose_basis(minkowski_octahedron_basis(), field_of(p)));
    return lattice;
}

template FamilyLattice<DInterval> enclose_insertion(Family, const DInterval&);
template FamilyLattice<Ball> enclose_insertion(Family, const Ball&);

}  // namespace superpack
