// The enclosure of D14 (Dostert & Vallentin 2020, Theorem 4.2) at p, the family's entry in the registry
// (family_registry.hpp); its equations are in families.hpp.
#include "family_enclosure.hpp"

#include <algorithm>

namespace superpack {

// D14: every root of the system with x >= 0 in the box d14_search_box (it holds [0,1] x [-1,1]^2,
// and the first equation bounds |x|, |y|, |z| by 1), then the branch: the one root with x, y,
// z certainly > 0 and y certainly < z (NOTES.md 4.1). Roots with x < 0 cannot be on the branch,
// so the half box suffices; the mirror root (x, z, y) (the same lattice reflected) has y > z.
template <class I>
FamilyLattice<I> enclose_d14(Family family, const I& p) {
    FamilyLattice<I> lattice{family};
    const auto field = field_of(p);
    auto equations = [&](const auto& v) { return d14_equations(v, p); };
    lattice.search = isolate_roots(equations, d14_search_box(p), 1e-7, 40000, 0.0);
    std::size_t undecided = 0;
    std::vector<std::size_t> on_branch, possibly;
    for (const RootLeaf<I>& leaf : lattice.search) {
        if (leaf.status == RootStatus::undecided) ++undecided;
        if (leaf.status != RootStatus::unique) continue;
        const I& x = leaf.root[0];
        const I& y = leaf.root[1];
        const I& z = leaf.root[2];
        // Off the branch only when a condition certainly fails: a box of x, y or z that merely
        // touches 0 leaves the root undecided.
        const I zero = field.integer(0);
        const bool off = certainly_less(x, zero) || certainly_less(y, zero) || certainly_less(z, zero) || certainly_less(z, y);
        const bool on = certainly_positive(x) && certainly_positive(y) && certainly_positive(z) && certainly_less(y, z);
        lattice.branches.push_back({{{"x", x}, {"y", y}, {"z", z}}, leaf});
        if (on) on_branch.push_back(lattice.branches.size() - 1);
        else if (!off) possibly.push_back(lattice.branches.size() - 1);
    }
    const std::string count = std::to_string(lattice.branches.size()) + " root(s) with x >= 0 certified";
    if (!possibly.empty()) {
        lattice.message = count + ", " + std::to_string(possibly.size()) +
                          " of them not certainly on or off the branch x, y, z > 0, y < z (it ends at p*_o = ln3/ln4, "
                          "where it meets its mirror y = z)";
        return lattice;
    }
    if (on_branch.empty()) {
        if (undecided > 0) {
            lattice.message = count + ", none with x, y, z > 0 and y < z; " + std::to_string(undecided) +
                              " pieces of the (x, y, z) box undecided";
            return lattice;
        }
        lattice.status = Outcome::refuted;
        lattice.message = count + ", none with x, y, z > 0 and y < z: no lattice on the Dostert-Vallentin branch";
        return lattice;
    }
    if (undecided > 0 || on_branch.size() != 1) {
        lattice.message = undecided > 0 ? std::to_string(undecided) + " pieces of the (x, y, z) box undecided"
                                        : std::to_string(on_branch.size()) + " roots with x, y, z > 0 and y < z";
        return lattice;
    }
    // The branch root first, as for O1; the others follow in the order of the search.
    std::rotate(lattice.branches.begin(), lattice.branches.begin() + static_cast<long>(on_branch.front()),
                lattice.branches.begin() + static_cast<long>(on_branch.front()) + 1);
    // Krawczyk on a wide piece stops once one step no longer halves the box; run again from the
    // root box (it holds the root, and so does every iterate) until the box stops shrinking. The
    // checker tightens its own box the same way (checker/claims/family_parameters.cpp).
    std::vector<I> root = lattice.branches.front().proof.root;
    for (int round = 0; round < 16; ++round) {
        const KrawczykResult<I> tighter = krawczyk_isolate(equations, root, 0.0, 60);
        if (tighter.status != RootStatus::unique) break;
        double before = 0, after = 0;
        for (std::size_t k = 0; k < root.size(); ++k) {
            before = std::max(before, width_upper(root[k]));
            after = std::max(after, width_upper(tighter.box[k]));
        }
        root = tighter.box;
        if (!(after < 0.5 * before)) break;
    }
    for (std::size_t k = 0; k < root.size(); ++k) lattice.branches.front().unknowns[k].value = root[k];
    lattice.parameters = lattice.branches.front().unknowns;
    finish(lattice, p, d14_basis(root[0], root[1], root[2]));
    return lattice;
}

template FamilyLattice<DInterval> enclose_d14(Family, const DInterval&);
template FamilyLattice<Ball> enclose_d14(Family, const Ball&);

}  // namespace superpack
