// One family at one p as JSON: parameters, basis, volume, determinant, phi, and the root
// proofs behind them (every real an outward-rounded enclosure).
#pragma once
#include "superpack/arith/enclosure_json.hpp"
#include "superpack/problems/families/families.hpp"

namespace superpack {

template <class I>
Json family_json(const FamilyLattice<I>& lattice);

template <class I>
Json root_leaf_json(const RootLeaf<I>& leaf);

}  // namespace superpack
