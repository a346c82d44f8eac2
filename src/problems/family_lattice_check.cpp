#include "superpack/problems/family_lattice_check.hpp"

#include <algorithm>

#include "superpack/problems/s6.hpp"

namespace superpack {

std::vector<Coefficients> family_contact_triples(Family family) {
    switch (family) {
        case Family::C0: return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, -1}, {1, 0, -1}, {1, 1, -1}};
        case Family::C1: return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, -1, 0}, {1, 0, -1}, {0, 1, -1}};
        case Family::O0: return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, -1}, {0, 1, -1}, {1, 1, -1}};
        case Family::O1: return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, -1, 0}, {1, 0, -1}};
        // b1, b2, b3, b1 + b2, b2 + b3, b1 + b3, b1 + b2 + b3: Minkowski's seven pairs.
        case Family::D14: return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}};
        // Minkowski's six pairs, contacts by the constraints n_i = 2 of the KKT system.
        case Family::S6: return s6_contact_triples();
    }
    return {};
}

int claimed_contacts(Family family) { return family == Family::D14 ? 14 : 12; }

template <class I>
LatticeCheck<I> check_family_lattice(const FamilyLattice<I>& lattice, const I& p) {
    if (!lattice.basis) {
        LatticeCheck<I> check;
        check.reason = std::string("no certified lattice: ") + lattice.message;
        return check;
    }
    const std::vector<Coefficients> identities = family_contact_triples(lattice.family);
    return check_lattice(*lattice.basis, p, [&](const Coefficients& c) {
        return std::find(identities.begin(), identities.end(), c) != identities.end();
    });
}

template LatticeCheck<DInterval> check_family_lattice(const FamilyLattice<DInterval>&, const DInterval&);
template LatticeCheck<Ball> check_family_lattice(const FamilyLattice<Ball>&, const Ball&);

}  // namespace superpack
