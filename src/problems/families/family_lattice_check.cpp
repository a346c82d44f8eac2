#include "superpack/problems/families/family_lattice_check.hpp"

#include <algorithm>

#include "superpack/problems/families/family_registry.hpp"

namespace superpack {

std::vector<Coefficients> family_contact_triples(Family family) { return family_definition(family).contact_triples; }

int claimed_contacts(Family family) { return family_definition(family).claimed_contacts; }

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
    // An exact lattice (the insertion's): its contacts at p = 1/2 are exact, and below 1/2 the
    // star-body test needs the exact p.
    if (const auto exact_basis = family_definition(lattice.family).exact_basis) return check_exact_lattice(exact_basis(), p, field);
    return check_family_lattice(lattice, field.rational(p));
}

template LatticeCheck<DInterval> check_family_lattice(const FamilyLattice<DInterval>&, const DInterval&);
template LatticeCheck<Ball> check_family_lattice(const FamilyLattice<Ball>&, const Ball&);
template LatticeCheck<DInterval> check_family_lattice(const FamilyLattice<DInterval>&, const Rational&);
template LatticeCheck<Ball> check_family_lattice(const FamilyLattice<Ball>&, const Rational&);

}  // namespace superpack
