// Which family is densest at one p among the lattices certified to be packings (the report's
// last column): a decision on certified enclosures, so it lives with the families, not in the
// command that prints it.
#pragma once
#include <string>
#include <vector>

#include "superpack/arith/outcome.hpp"
#include "superpack/problems/families/families.hpp"

namespace superpack {

// Among the lattices certified to be packings (verdicts[k] for lattices[k]): the family whose
// phi is certainly above every other's, or those that cannot be separated from the best (joined
// by '='), or "none".
template <class I>
std::string densest_family(const std::vector<FamilyLattice<I>>& lattices, const std::vector<Outcome>& verdicts) {
    std::vector<const FamilyLattice<I>*> certified;
    for (std::size_t k = 0; k < lattices.size(); ++k)
        if (lattices[k].phi && verdicts[k] == Outcome::proved) certified.push_back(&lattices[k]);
    if (certified.empty()) return "none";
    // The leader by midpoint: any certified lattice not certainly below it ties with it.
    const FamilyLattice<I>* leader = certified.front();
    for (const auto* lattice : certified)
        if (mid_double(*lattice->phi) > mid_double(*leader->phi)) leader = lattice;
    std::string names = to_string(leader->family);
    bool alone = true;
    for (const auto* lattice : certified)
        if (lattice != leader && !certainly_less(*lattice->phi, *leader->phi)) {
            names += std::string("=") + to_string(lattice->family);
            alone = false;
        }
    return alone ? names : names + " (not separated)";
}

}  // namespace superpack
