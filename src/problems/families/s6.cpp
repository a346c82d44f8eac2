// The enclosure of S6 (superpack's own family, NOTES.md 4.2) at p, the family's entry in the registry
// (family_registry.hpp); its KKT system is in local_optimality.hpp, its triples in s6_definition.hpp.
#include "family_enclosure.hpp"

#include "superpack/arith/contract.hpp"
#include "superpack/problems/optimality/local_optimality.hpp"
#include "superpack/problems/families/s6_definition.hpp"

namespace superpack {

// S6 (NOTES.md 4.2): the KKT point of min det B subject to ||c_i B||_(2p) = 2 for the six
// triples of s6_contact_triples, on the branch through the seed at p = 9/10. The
// floating-point continuation (s6_guess) only guesses it; Krawczyk on kkt_equations proves
// exactly one KKT point in a small box about the guess, and the basis is that root box. A step
// that fails leaves S6 undecided with the reason, never another lattice.
template <class I>
FamilyLattice<I> enclose_s6(Family family, const I& p) {
    FamilyLattice<I> lattice{family};
    const auto field = field_of(p);
    if (!certainly_less(octahedral_crossover(p), p)) {
        lattice.message = "p is not certainly above p*_o = ln3/ln4 at this precision, where S6 begins (try --digits 30)";
        return lattice;
    }
    if (!certainly_less(p, field.integer(1))) {
        lattice.message = "p is not certainly below 1, where S6 ends (at p = 1 rotations leave no isolated KKT point)";
        return lattice;
    }
    std::string failure;
    const std::optional<KktPoint> guess = s6_guess(mid_double(p), failure);
    if (!guess) {
        lattice.message = failure;
        return lattice;
    }
    const std::vector<Coefficients>& triples = s6_contact_triples();
    const Contracted<KrawczykResult<I>> isolated = within_contract([&] { return isolate_kkt_point(*guess, triples, p); });
    if (isolated.status == ContractStatus::too_wide) {
        lattice.message = isolated.reason();
        return lattice;
    }
    const KrawczykResult<I>& root = *isolated.value;
    lattice.search.push_back({root.initial_box, root.status, root.box, root.reason});
    if (root.status != RootStatus::unique) {
        lattice.message = "Krawczyk did not prove a unique KKT point near the continued guess (" + root.reason + ")";
        return lattice;
    }
    std::vector<NamedValue<I>> unknowns;
    for (int k = 0; k < 9; ++k)
        unknowns.push_back({"b" + std::to_string(k / 3) + std::to_string(k % 3), root.box[static_cast<std::size_t>(k)]});
    for (std::size_t i = 0; i < triples.size(); ++i) unknowns.push_back({"mu" + std::to_string(i + 1), root.box[9 + i]});
    lattice.branches.push_back({unknowns, lattice.search.back()});
    lattice.parameters = unknowns;
    const std::vector<I>& x = root.box;
    finish(lattice, p, Basis<I>{{{x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}}});
    return lattice;
}

template FamilyLattice<DInterval> enclose_s6(Family, const DInterval&);
template FamilyLattice<Ball> enclose_s6(Family, const Ball&);

}  // namespace superpack
