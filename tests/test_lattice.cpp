// The lattice checker against hand-made lattices of known answer and independent mpmath values
// (scripts/make_lattice_data.py -> tests/data/lattice.json).
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <set>

#include "superpack/problems/families/family_lattice_check.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

const nlohmann::json& lattice_data() {
    static const nlohmann::json data = [] {
        std::ifstream file(std::string(SUPERPACK_TEST_DATA) + "/lattice.json");
        return nlohmann::json::parse(file);
    }();
    return data;
}

const std::string minkowski = "2/3,2/3,-2/3; -1/3,4/3,-1/3; 1/3,-1/3,-4/3";

// Re-check a witness independently of the checker: rebuild v from the exact basis in rationals
// and enclose its norm at 128 bits; it must be certainly < 2 and meet the reported norm.
template <class I>
void recheck_witness(const Basis<Rational>& basis, const Rational& p, const LatticeVector<I>& witness) {
    const BallField field{128};
    std::vector<Ball> v;
    for (int j = 0; j < 3; ++j) {
        Rational x = 0;
        for (int i = 0; i < 3; ++i) x += witness.coefficients[i] * basis[i][j];
        v.push_back(field.rational(x));
    }
    const Ball two_p = field.integer(2) * field.rational(p);
    const Ball norm = pow_nonneg(gauge_power(v, two_p), field.integer(1) / two_p);
    CHECK(certainly_less(norm, field.integer(2)));
    CHECK(overlaps(norm, as_ball(witness.norm)));
}

std::set<Coefficients> pairs(const nlohmann::json& list) {
    std::set<Coefficients> result;
    for (const auto& c : list) {
        const Coefficients a{c[0].get<long>(), c[1].get<long>(), c[2].get<long>()};
        result.insert(a);
        result.insert({-a[0], -a[1], -a[2]});
    }
    return result;
}

}  // namespace

TEMPLATE_TEST_CASE("the published families at the acceptance points: 12 contacts", "", Binary64, Arb128) {
    const TestType field;
    for (const auto& [family, p_text] : std::vector<std::pair<Family, std::string>>{
             {Family::C0, "2"}, {Family::C1, "3"}, {Family::O0, "0.85"}}) {
        INFO(to_string(family) << " at p = " << p_text);
        const Rational p = parse_rational(p_text);
        const auto lattice = enclose_family(family, p, field);
        const auto check = check_family_lattice(lattice, field.rational(p));
        CHECK(check.verdict == Outcome::proved);
        CHECK(check.contacts() == 12);
        CHECK(check.near_contacts.empty());
        REQUIRE(check.min_norm);
        CHECK(meets(*check.min_norm, "2"));
        // The contacts are exactly the family's identities, with both signs.
        std::set<Coefficients> expected;
        for (const auto& c : family_contact_triples(family)) {
            expected.insert(c);
            expected.insert({-c[0], -c[1], -c[2]});
        }
        CHECK(std::set<Coefficients>(check.contact_vectors.begin(), check.contact_vectors.end()) == expected);
    }
}

// At p = 10^4 a norm near 2 has 2^(2p) in its 2p-th power, beyond binary64's range: the norm is
// taken of v/2 (before, binary64 left (1, 1, 0) and (1, -1, 0) of C0 undecided, norm [-inf, inf]).
TEMPLATE_TEST_CASE("C0 and C1 at p = 10^4 and 10^6: packings with the family's 12 contacts", "", Binary64, Arb128) {
    const TestType field;
    for (const char* p_text : {"10000", "1000000"})
        for (Family family : {Family::C0, Family::C1}) {
            INFO(to_string(family) << " at p = " << p_text);
            const Rational p = parse_rational(p_text);
            const auto check = check_family_lattice(enclose_family(family, p, field), field.rational(p));
            CHECK(check.verdict == Outcome::proved);
            CHECK(check.contacts() == 12);
            REQUIRE(check.min_norm);
            CHECK(meets(*check.min_norm, "2"));
        }
}

TEMPLATE_TEST_CASE("Minkowski's octahedron lattice at p = 1/2: 14 contacts, decided exactly", "", Binary64, Arb128) {
    const TestType field;
    const auto check = check_exact_lattice(parse_basis(minkowski), Rational(1, 2), field);
    CHECK(check.verdict == Outcome::proved);
    CHECK(check.contacts() == 14);
    const auto& contacts = check.contact_vectors;
    CHECK(std::set<Coefficients>(contacts.begin(), contacts.end()) == pairs(lattice_data()["minkowski_short"]));
}

TEMPLATE_TEST_CASE("FCC at p = 1, scaled above and below the sphere contact distance", "", Binary64, Arb128) {
    const TestType field;
    const Rational p(1);
    const auto packing = check_exact_lattice(parse_basis("3/2,3/2,0; 3/2,0,3/2; 0,3/2,3/2"), p, field);
    CHECK(packing.verdict == Outcome::proved);
    CHECK(packing.contacts() == 0);
    REQUIRE(packing.min_norm);
    CHECK(meets(*packing.min_norm, lattice_data()["fcc_3_2_min_norm"]));
    const Basis<Rational> tight = parse_basis("7/5,7/5,0; 7/5,0,7/5; 0,7/5,7/5");
    const auto overlap = check_exact_lattice(tight, p, field);
    CHECK(overlap.verdict == Outcome::refuted);
    REQUIRE(overlap.witness);
    CHECK(meets(overlap.witness->norm, lattice_data()["fcc_7_5_min_norm"]));
    recheck_witness(tight, p, *overlap.witness);
}

TEMPLATE_TEST_CASE("the cubic lattice 2Z^3: 6 contacts, exactly, for integer and non-integer 2p", "", Binary64, Arb128) {
    const TestType field;
    for (const std::string p_text : {"1", "3", "0.85", "7/9"}) {
        INFO("p = " << p_text);
        const auto check = check_exact_lattice(parse_basis("2,0,0; 0,2,0; 0,0,2"), parse_rational(p_text), field);
        CHECK(check.verdict == Outcome::proved);
        CHECK(check.contacts() == 6);
    }
    // (1, 1, 0) in the lattice spanned by (1,1,0): at p = 1/2 its norm is 2 (equal magnitudes rule).
    const auto l1 = check_exact_lattice(parse_basis("1,1,0; 0,2,0; 0,0,2"), Rational(1, 2), field);
    CHECK(l1.verdict == Outcome::proved);
    // Lattice {(a, a + 2b, 2c)}: norm-1 distance 2 is reached by (1,1,0), (1,-1,0), (0,2,0), (0,0,2),
    // (2,0,0) and their negatives, and by nothing shorter.
    CHECK(l1.contacts() == 10);
}

TEST_CASE("a near contact is undecided in binary64 and decided with more bits") {
    // (2 + 10^-30, 0, 0) has norm 2 + 10^-30 > 2: binary64 cannot separate it from 2.
    const std::string basis = "2.000000000000000000000000000001,0,0; 0,2,0; 0,0,2";
    const auto coarse = check_exact_lattice(parse_basis(basis), Rational(1), DoubleField{});
    CHECK(coarse.verdict == Outcome::undecided);
    REQUIRE(coarse.near_contacts.size() == 1);
    CHECK(coarse.near_contacts[0].coefficients == Coefficients{1, 0, 0});
    const auto fine = check_exact_lattice(parse_basis(basis), Rational(1), BallField{256});
    CHECK(fine.verdict == Outcome::proved);
    CHECK(fine.contacts() == 4);
}

TEMPLATE_TEST_CASE("a vector of norm 1.9 at p = 2 is a witness of overlap", "", Binary64, Arb128) {
    const TestType field;
    const Basis<Rational> skew = parse_basis("3.9,2,0; -2,-2,0; 0,0,2");
    const auto check = check_exact_lattice(skew, Rational(2), field);
    CHECK(check.verdict == Outcome::refuted);
    REQUIRE(check.witness);
    const auto& shortest = lattice_data()["skew_p2_shortest"];
    CHECK(check.witness->coefficients == Coefficients{shortest[0], shortest[1], shortest[2]});
    CHECK(meets(check.witness->norm, lattice_data()["skew_p2_min_norm"]));
    REQUIRE(check.min_norm);
    CHECK(meets(*check.min_norm, lattice_data()["skew_p2_min_norm"]));
    recheck_witness(skew, Rational(2), *check.witness);
}

TEMPLATE_TEST_CASE("the published O1 lattice overlaps at p = 0.6 (erratum), witness e1 - e2 - e3", "", Binary64, Arb128) {
    const TestType field;
    const Rational p = parse_rational("0.6");
    const auto lattice = enclose_family(Family::O1, p, field);
    const auto check = check_family_lattice(lattice, field.rational(p));
    CHECK(check.verdict == Outcome::refuted);
    REQUIRE(check.witness);
    CHECK(check.witness->coefficients == Coefficients{1, -1, -1});
    CHECK(meets(check.witness->norm, lattice_data()["o1_p0.6_witness_norm"]));
    CHECK(certainly_less(check.witness->norm, field.integer(2)));
    // The checker's short vectors agree with the brute force (norm <= 2 + 1e-7, one per pair).
    std::set<Coefficients> found(check.contact_vectors.begin(), check.contact_vectors.end());
    found.insert(check.witness->coefficients);
    found.insert({-1, 1, 1});
    CHECK(found == pairs(lattice_data()["o1_p0.6_short"]));
}

TEST_CASE("singular and malformed bases are input errors") {
    CHECK_THROWS_AS(parse_basis("1,0,0; 0,1,0; 1,1,0"), InputError);
    CHECK_THROWS_AS(parse_basis("1,0,0; 0,1,0"), InputError);
    CHECK_THROWS_AS(parse_basis("1,0; 0,1,0; 0,0,1"), InputError);
    CHECK_THROWS_AS(parse_basis("1,x,0; 0,1,0; 0,0,1"), InputError);
    CHECK_THROWS_AS(check_exact_lattice(parse_basis(minkowski), parse_rational("0"), DoubleField{}), InputError);
}

TEST_CASE("check-lattice exit codes: overlap is a certified answer (0), bad input 2, undecided 4") {
    auto exit_code = [](const std::string& arguments) {
        const int status = std::system((std::string(SUPERPACK_BINARY) + " check-lattice " + arguments + " >/dev/null 2>&1").c_str());
        return WEXITSTATUS(status);
    };
    CHECK(exit_code("--p 0.5 --basis \"" + minkowski + "\"") == 0);
    CHECK(exit_code("--p 2 --basis \"3.9,2,0; -2,-2,0; 0,0,2\"") == 0);
    CHECK(exit_code("--p 2 --basis \"1,0,0; 0,1,0; 1,1,0\"") == 2);
    CHECK(exit_code("--p 2 --basis \"1,0,0; 0,1\"") == 2);
    CHECK(exit_code("--p 2 --family C0 --basis \"1,0,0; 0,1,0; 0,0,1\"") == 2);
    CHECK(exit_code("--p 1 --basis \"2.000000000000000000000000000001,0,0; 0,2,0; 0,0,2\"") == 4);
    CHECK(exit_code("--p 1 --basis \"2.000000000000000000000000000001,0,0; 0,2,0; 0,0,2\" --digits 60") == 0);
}
