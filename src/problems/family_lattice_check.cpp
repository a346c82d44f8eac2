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
        // No contact equations: the basis is exact, and check_family_lattice with the exact p
        // decides its contacts exactly.
        case Family::MinkowskiInsertion: return {};
    }
    return {};
}

int claimed_contacts(Family family) { return family == Family::D14 ? 14 : 12; }

namespace {

template <class I>
LatticeCheck<I> uncertified(const FamilyLattice<I>& lattice) {
    LatticeCheck<I> check;
    check.reason = std::string("no certified lattice: ") + lattice.message;
    return check;
}

}  // namespace

template <class I>
LatticeCheck<I> check_family_lattice(const FamilyLattice<I>& lattice, const I& p) {
    if (!lattice.basis) return uncertified(lattice);
    const std::vector<Coefficients> identities = family_contact_triples(lattice.family);
    return check_lattice(*lattice.basis, p, [&](const Coefficients& c) {
        return std::find(identities.begin(), identities.end(), c) != identities.end();
    });
}

template <class I>
LatticeCheck<I> check_family_lattice(const FamilyLattice<I>& lattice, const Rational& p) {
    if (!lattice.basis) return uncertified(lattice);
    const auto field = field_of((*lattice.basis)[0][0]);
    // The insertion's lattice is exact: its contacts at p = 1/2 are exact, and below 1/2 the
    // star-body test needs the exact p.
    if (lattice.family == Family::MinkowskiInsertion) return check_exact_lattice(minkowski_octahedron_basis(), p, field);
    return check_family_lattice(lattice, field.rational(p));
}

template LatticeCheck<DInterval> check_family_lattice(const FamilyLattice<DInterval>&, const DInterval&);
template LatticeCheck<Ball> check_family_lattice(const FamilyLattice<Ball>&, const Ball&);
template LatticeCheck<DInterval> check_family_lattice(const FamilyLattice<DInterval>&, const Rational&);
template LatticeCheck<Ball> check_family_lattice(const FamilyLattice<Ball>&, const Rational&);

}  // namespace superpack
