#include "superpack/problems/families/families.hpp"

#include "superpack/problems/families/family_registry.hpp"

namespace superpack {

const char* to_string(Family family) { return family_definition(family).name; }

std::vector<Family> all_families() {
    std::vector<Family> families;
    for (const FamilyDefinition& definition : family_registry())
        if (definition.convex) families.push_back(definition.family);
    return families;
}

std::vector<Family> convex_families_and_insertion() {
    std::vector<Family> families = all_families();
    for (const FamilyDefinition& definition : family_registry())
        if (!definition.convex) families.push_back(definition.family);
    return families;
}

std::string family_source(Family family) { return family_definition(family).source; }

Family parse_family(const std::string& name) {
    for (const FamilyDefinition& definition : family_registry())
        if (name == definition.name) return definition.family;
    std::string expected;
    const std::vector<FamilyDefinition>& registry = family_registry();
    for (std::size_t k = 0; k < registry.size(); ++k)
        expected += (k == 0 ? "" : k + 1 == registry.size() ? " or " : ", ") + std::string(registry[k].name);
    throw InputError("unknown family '" + name + "' (expected " + expected + ")");
}

Basis<Rational> minkowski_octahedron_basis() {
    return Basis<Rational>{{{Rational(2, 3), Rational(2, 3), Rational(-2, 3)},
                            {Rational(-1, 3), Rational(4, 3), Rational(-1, 3)},
                            {Rational(1, 3), Rational(-1, 3), Rational(-4, 3)}}};
}

std::string family_domain_text(Family family) { return family_definition(family).domain_text; }

void require_in_domain(Family family, const Rational& p) {
    DomainMembership membership = family_domain(family, p);
    if (!membership.inside()) throw InputError(membership.reason);
}

template <class I>
FamilyLattice<I> enclose_family_at(Family family, const I& p) {
    return enclosure_for(family_definition(family), p)(family, p);
}

FamilyLattice<DInterval> enclose_family(Family family, const Rational& p, const DoubleField& field) {
    require_in_domain(family, p);
    return enclose_family_at(family, field.rational(p));
}

FamilyLattice<Ball> enclose_family(Family family, const Rational& p, const BallField& field) {
    require_in_domain(family, p);
    return enclose_family_at(family, field.rational(p));
}

template FamilyLattice<DInterval> enclose_family_at(Family, const DInterval&);
template FamilyLattice<Ball> enclose_family_at(Family, const Ball&);

}  // namespace superpack
