#include "superpack/cert/family_certificate.hpp"

#include <stdexcept>

#include "superpack/arith/decimal.hpp"
#include "superpack/cert/certificate_partition.hpp"
#include "superpack/problems/families/family_registry.hpp"

namespace superpack {

namespace {

// C0, C1: the Newton box of s (with the first Newton step recomputed for the record) and
// the root-free partition of [0, lower end of that box].
template <class I>
Json cubic_proof(const FamilyLattice<I>& lattice, const I& p) {
    const Family family = lattice.family;
    const RootLeaf<I>& newton = lattice.search.back();
    const I& box = newton.piece[0];
    auto equation = [&](const auto& s) { return cubic_equation(family, s, p); };
    const I derivative = equation(variable(box)).derivative;
    const I center = midpoint(box);
    const I image = center - equation(center) / derivative;
    Json newton_leaf{{"kind", "newton"},
                     {"box", box_json(std::vector<I>{box})},
                     {"midpoint", box_json(std::vector<I>{center})},
                     {"derivative", box_json(std::vector<I>{derivative})},
                     {"image", box_json(std::vector<I>{image})},
                     {"root", box_json(newton.root)}};
    const std::vector<RootLeaf<I>> below(lattice.search.begin(), lattice.search.end() - 1);
    const std::vector<I> search_box{hull(field_of(p).integer(0), lower_point(box))};
    auto vector_equation = [&](const std::vector<I>& x) { return std::vector<I>{equation(x[0])}; };
    Json cases = Json::array();
    cases.push_back(newton_leaf);
    cases.push_back(partition_json(vector_equation, search_box, below));
    return Json{{"kind", "all"}, {"cases", cases}};
}

template <class I>
Json o1_proof(const FamilyLattice<I>& lattice, const I& p) {
    const auto field = field_of(p);
    auto equations = [&](const std::vector<I>& x) { return o1_equations(x, p); };
    const std::vector<I> box{hull(field.integer(0), field.integer(1)), hull(field.integer(-1), field.integer(1))};
    Json cases = Json::array();
    cases.push_back(partition_json(equations, box, lattice.search));
    return Json{{"kind", "all"}, {"cases", cases}};
}

// D14: the partition of the search box (every root with x >= 0); the checker picks the branch.
template <class I>
Json d14_proof(const FamilyLattice<I>& lattice, const I& p) {
    auto equations = [&](const std::vector<I>& v) { return d14_equations(v, p); };
    Json cases = Json::array();
    cases.push_back(partition_json(equations, d14_search_box(p), lattice.search));
    return Json{{"kind", "all"}, {"cases", cases}};
}

// S6: the Krawczyk leaf of the KKT point over (b00, ..., b22, mu1, ..., mu6), the format of the
// local-optimum kind (NOTES.md 8.9): the box the proof is about and the root box in it.
template <class I>
Json s6_proof(const FamilyLattice<I>& lattice, const I&) {
    const RootLeaf<I>& leaf = lattice.search.front();
    return Json{{"kind", "krawczyk"}, {"status", "unique"}, {"box", box_json(leaf.piece)}, {"root", box_json(leaf.root)}};
}

// O0: its parameter c is a closed form of p, which the checker evaluates itself.
template <class I>
Json evaluation_proof(const FamilyLattice<I>&, const I&) {
    return Json{{"kind", "evaluation"}};
}

// The certificate side of each family's registry entry (family_registry.hpp), a table of its
// own because certificates are a layer above the registry: the proof of the family's
// parameters at p, or why the family has no certificate kind.
template <class I>
using ParameterProof = Json (*)(const FamilyLattice<I>& lattice, const I& p);

struct FamilyProof {
    Family family;
    ParameterProof<DInterval> on_double;
    ParameterProof<Ball> on_ball;
    const char* no_certificate;  // when the family has none
};

const FamilyProof& family_proof(Family family) {
    static const std::vector<FamilyProof> proofs{
        {Family::C0, cubic_proof<DInterval>, cubic_proof<Ball>, nullptr},
        {Family::C1, cubic_proof<DInterval>, cubic_proof<Ball>, nullptr},
        {Family::O0, evaluation_proof<DInterval>, evaluation_proof<Ball>, nullptr},
        {Family::O1, o1_proof<DInterval>, o1_proof<Ball>, nullptr},
        {Family::D14, d14_proof<DInterval>, d14_proof<Ball>, nullptr},
        {Family::S6, s6_proof<DInterval>, s6_proof<Ball>, nullptr},
        // The insertion has no family certificate of its own: its lattice (Minkowski's, exact) is
        // certified through the star-lattice-check kind, which takes one exact p.
        {Family::MinkowskiInsertion, nullptr, nullptr,
         "--certificate: no certificate kind for the family minkowski-insertion (its basis is exact and the same for every p: there is no parameter to prove); "
         "check-lattice --family minkowski-insertion --certificate certifies its exact basis"},
    };
    for (const FamilyProof& proof : proofs)
        if (proof.family == family) return proof;
    throw std::logic_error("a family without its parameter proof in family_certificate.cpp");
}

ParameterProof<DInterval> parameter_proof(const FamilyProof& proof, const DInterval&) { return proof.on_double; }
ParameterProof<Ball> parameter_proof(const FamilyProof& proof, const Ball&) { return proof.on_ball; }

bool canonical(const Coefficients& c) {
    for (long x : c)
        if (x != 0) return x > 0;
    return false;
}

}  // namespace

template <class I>
Json family_parameter_proof(const FamilyLattice<I>& lattice, const I& p) {
    if (lattice.status != Outcome::proved)
        throw std::runtime_error(std::string("certificate: ") + to_string(lattice.family) + " is not certified at this p");
    const auto proof = parameter_proof(family_proof(lattice.family), p);
    if (!proof) throw std::logic_error("certificate: no certificate kind for " + std::string(to_string(lattice.family)));
    return proof(lattice, p);
}

void require_certificate_kind(const Rational& p, std::optional<Family> family) {
    if (family) require_in_domain(*family, p);  // the first problem named is the domain's
    if (family && family_proof(*family).no_certificate) throw InputError(family_proof(*family).no_certificate);
}

Json family_definition_json(Family family) {
    if (!family_definition(family).defined_by_contact_pairs) return Json::object();
    Json pairs = Json::array();
    for (const Coefficients& c : family_definition(family).contact_triples) pairs.push_back(coefficients_json(c));
    return Json{{"contact_pairs", pairs}};
}

template <class I>
Json lattice_verdict_json(const LatticeCheck<I>& check) {
    if (check.verdict == Outcome::proved) {
        Json vectors = Json::array();
        for (const auto& c : check.contact_vectors) vectors.push_back(coefficients_json(c));
        return Json{{"verdict", "packing"}, {"contacts", check.contacts()}, {"contact_vectors", vectors}};
    }
    if (check.verdict == Outcome::refuted)
        return Json{{"verdict", "overlapping"},
                    {"witness", Json{{"coefficients", coefficients_json(check.witness->coefficients)},
                                     {"norm", exact_interval_json(check.witness->norm)}}}};
    return Json{{"verdict", "undecided"}};
}

template <class I>
Json lattice_enumeration_json(const LatticeCheck<I>& check) {
    if (check.verdict != Outcome::proved) return Json(nullptr);
    Json contacts = Json::array();
    for (const auto& c : check.contact_vectors)
        if (canonical(c)) contacts.push_back(Json{{"coefficients", coefficients_json(c)}});
    return Json{{"kind", "enumeration"}, {"coefficient_bound", coefficients_json(check.coefficient_bound)}, {"contacts", contacts}};
}

template <class Field>
Json family_certificate(const FamilyLattice<typename Field::Interval>& lattice, const Rational& p, const Field& field,
                        long digits) {
    using I = typename Field::Interval;
    if (lattice.status != Outcome::proved)
        throw std::runtime_error(std::string("certificate: ") + to_string(lattice.family) + " is not certified at this p");
    const I p_interval = field.rational(p);
    // Whether the lattice is a packing: only a proved packing lets the claim call phi a packing
    // density; an undecided check leaves phi = V_sb / |det B| and says so. phi certainly > 1
    // already rules a packing out (the checker says so from phi), and that is where the
    // enumeration box is huge (O0 near p = 1/2: minutes), so it is not enumerated then.
    const LatticeCheck<I> check =
        certainly_less(field.integer(1), *lattice.phi) ? LatticeCheck<I>{} : check_family_lattice(lattice, p_interval);
    Json parameters = Json::object();
    for (const auto& parameter : lattice.parameters) parameters[parameter.name] = exact_interval_json(parameter.value);
    const std::string family = to_string(lattice.family);
    Json data = lattice_verdict_json(check);
    data.update(Json{{"family", family},
                     {"p", rational_text(p)},
                     {"parameters", parameters},
                     {"volume", exact_interval_json(*lattice.volume)},
                     {"determinant", exact_interval_json(*lattice.determinant)},
                     {"phi", exact_interval_json(*lattice.phi)}});
    data.update(family_definition_json(lattice.family));
    Json claim{{"kind", "family-lattice"}, {"data", data}};
    Json inputs{{"family", family}, {"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}};
    const Json proof{{"kind", "family-lattice"},
                     {"parameters", family_parameter_proof(lattice, p_interval)},
                     {"lattice", lattice_enumeration_json(check)}};
    return certificate_document(certificate_head("density", field, digits), claim, inputs, proof);
}

template Json family_parameter_proof(const FamilyLattice<DInterval>&, const DInterval&);
template Json family_parameter_proof(const FamilyLattice<Ball>&, const Ball&);
template Json lattice_verdict_json(const LatticeCheck<DInterval>&);
template Json lattice_verdict_json(const LatticeCheck<Ball>&);
template Json lattice_enumeration_json(const LatticeCheck<DInterval>&);
template Json lattice_enumeration_json(const LatticeCheck<Ball>&);
template Json family_certificate(const FamilyLattice<DInterval>&, const Rational&, const DoubleField&, long);
template Json family_certificate(const FamilyLattice<Ball>&, const Rational&, const BallField&, long);

}  // namespace superpack
