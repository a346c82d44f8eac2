// The enclosure of O1 (JST 2009, Eqs. 11-13) at p, the family's entry in the registry
// (family_registry.hpp); its equations are in families.hpp.
#include "family_enclosure.hpp"

#include <algorithm>

namespace superpack {

// O1: every root of Eq. 12 with q >= 0 (roots come in pairs q, -q) in the box
// [0, 1] x [-1, 1], which holds all real roots since 2|q|^2p + |s|^2p = 1.
template <class I>
FamilyLattice<I> enclose_o1(Family family, const I& p) {
    FamilyLattice<I> lattice{family};
    const auto field = field_of(p);
    auto equations = [&](const auto& x) { return o1_equations(x, p); };
    const std::vector<I> box{hull(field.integer(0), field.integer(1)), hull(field.integer(-1), field.integer(1))};
    lattice.search = isolate_roots(equations, box, 1e-7, 20000, 0.0);
    std::size_t undecided = 0;
    for (const RootLeaf<I>& leaf : lattice.search) {
        if (leaf.status == RootStatus::unique) lattice.branches.push_back({{{"q", leaf.root[0]}, {"s", leaf.root[1]}}, leaf});
        if (leaf.status == RootStatus::undecided) ++undecided;
    }
    std::sort(lattice.branches.begin(), lattice.branches.end(), [](const RootBranch<I>& a, const RootBranch<I>& b) {
        return mid_double(a.unknowns[1].value) > mid_double(b.unknowns[1].value);
    });
    const I crossover = octahedral_crossover(p);
    const bool before = certainly_less(p, crossover), after = certainly_less(crossover, p);
    // Beyond p*_o there is no lattice on the branch whatever the search finds: the roots are
    // listed for information only, so undecided pieces (at large p, where the equations are
    // nearly flat in q) do not make the verdict undecided.
    if (after) {
        lattice.status = Outcome::refuted;
        lattice.message = "the Minkowski branch of Eq. (12) ends at p*_o = ln3/ln4; here Eq. (12) has " +
                          std::to_string(lattice.branches.size()) + " root(s) with q >= 0" +
                          (undecided > 0 ? " certified (" + std::to_string(undecided) + " pieces of the (q, s) box undecided)" : "") +
                          ", none on that branch";
        return lattice;
    }
    if (undecided > 0) {
        lattice.message = std::to_string(undecided) + " pieces of the (q, s) box undecided";
        return lattice;
    }
    if (!before || lattice.branches.size() != 2) {
        lattice.message = "expected two roots of Eq. (12) below p*_o, found " + std::to_string(lattice.branches.size());
        return lattice;
    }
    // Below p*_o the Minkowski branch is the root with the larger s (NOTES.md, "O1 branches").
    const I& q = lattice.branches[0].unknowns[0].value;
    const I& s = lattice.branches[0].unknowns[1].value;
    lattice.parameters = {{"l", o1_l(p)}, {"q", q}, {"s", s}};
    finish(lattice, p, o1_basis(q, s, p));
    return lattice;
}

template FamilyLattice<DInterval> enclose_o1(Family, const DInterval&);
template FamilyLattice<Ball> enclose_o1(Family, const Ball&);

}  // namespace superpack
