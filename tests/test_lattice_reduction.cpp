// Exact LLL reduction of the basis before the enumeration (NOTES.md 5.6): skewed bases of simple
// lattices are decided, results come back in the given basis, the transform is unimodular and
// exact, and a unimodular change of basis changes neither verdict nor contacts.
#include <random>
#include <set>

#include "checker/verifier.hpp"
#include "superpack/problems/families/family_lattice_check.hpp"
#include "superpack/cert/lattice_certificate.hpp"
#include "support.hpp"
#include "tamper.hpp"

using namespace superpack;
using namespace superpack::test;
using superpack::test::rejected_at;

namespace {

Rational det(const Transform& u) {
    Basis<Rational> m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = u[i][j];
    return determinant(m);
}

Basis<Rational> times(const Transform& u, const Basis<Rational>& basis) {
    Basis<Rational> result;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) result[i][j] = u[i][0] * basis[0][j] + u[i][1] * basis[1][j] + u[i][2] * basis[2][j];
    return result;
}

std::set<Coefficients> with_signs(const std::vector<Coefficients>& list) {
    std::set<Coefficients> result;
    for (const Coefficients& c : list) {
        result.insert(c);
        result.insert({-c[0], -c[1], -c[2]});
    }
    return result;
}

// A random unimodular matrix: `steps` elementary row operations with multipliers up to `size`,
// and a sign change.
Transform random_unimodular(std::mt19937& random, int size, int steps) {
    Transform u = identity_transform();
    std::uniform_int_distribution<int> row(0, 2), multiplier(-size, size);
    for (int step = 0; step < steps; ++step) {
        const int i = row(random), j = (i + 1 + row(random) % 2) % 3;
        const long k = multiplier(random);
        for (int c = 0; c < 3; ++c) u[i][c] += k * u[j][c];
    }
    for (long& x : u[row(random)]) x = -x;
    return u;
}

std::string basis_text(const Basis<Rational>& basis) {
    std::string text;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) text += rational_text(basis[i][j]) + (j < 2 ? "," : i < 2 ? ";" : "");
    return text;
}

}  // namespace

TEST_CASE("the LLL transform is integral, unimodular and gives the reduced basis exactly") {
    for (const char* text : {"2,0,0; 2000,2,0; 0,0,2", "2,0,0; 0,2,0; 0,0,0.001", "1/3,7/5,2; 1000001/7,3,-1; 5,5,5"}) {
        INFO(text);
        const Basis<Rational> basis = parse_basis(text);
        const BasisReduction reduction = reduce_basis(basis);
        REQUIRE(reduction.done);
        CHECK(abs(det(reduction.transform)) == 1);
        CHECK(times(reduction.transform, basis) == reduction.reduced);
    }
    const BasisReduction cube = reduce_basis(parse_basis("2,0,0; 2000,2,0; 0,0,2"));
    for (const auto& row : cube.reduced) CHECK(row[0] * row[0] + row[1] * row[1] + row[2] * row[2] == 4);
}

// Before the reduction both were undecided: "the coefficient box is too large to enumerate".
TEMPLATE_TEST_CASE("a flat and a skewed basis are decided, in the given basis, at several p", "", Binary64, Arb128) {
    const TestType field;
    const Basis<Rational> flat = parse_basis("2,0,0; 0,2,0; 0,0,0.001");
    const Basis<Rational> skewed = parse_basis("2,0,0; 2000,2,0; 0,0,2");  // a basis of 2Z^3
    for (const char* p_text : {"0.5", "0.85", "1", "2", "3", "1000000"}) {
        INFO("p = " << p_text);
        const Rational p = parse_rational(p_text);
        const auto overlap = check_exact_lattice(flat, p, field);
        CHECK(overlap.verdict == Outcome::refuted);
        REQUIRE(overlap.witness);
        CHECK(overlap.witness->coefficients == Coefficients{0, 0, 1});  // e3 = (0, 0, 0.001)
        CHECK(meets(overlap.witness->norm, "0.001"));
        REQUIRE(overlap.min_norm);
        CHECK(meets(*overlap.min_norm, "0.001"));
        const auto packing = check_exact_lattice(skewed, p, field);
        CHECK(packing.verdict == Outcome::proved);
        CHECK(packing.contacts() == 6);
        // +-2 e_i: e1, e2 - 1000 e1 and e3 of the given basis.
        CHECK(with_signs(packing.contact_vectors) == with_signs({{1, 0, 0}, {-1000, 1, 0}, {0, 0, 1}}));
    }
}

TEMPLATE_TEST_CASE("random unimodular changes of basis keep the verdict and the contacts", "", Binary64, Arb128) {
    const TestType field;
    std::mt19937 random(2009);
    struct Known {
        const char* basis;
        const char* p;
        Outcome verdict;
        std::size_t contacts;
    };
    for (const Known& known : {Known{"2/3,2/3,-2/3; -1/3,4/3,-1/3; 1/3,-1/3,-4/3", "1/2", Outcome::proved, 14},
                               Known{"2,0,0; 0,2,0; 0,0,2", "2", Outcome::proved, 6},
                               Known{"1,1,0; 0,2,0; 0,0,2", "1/2", Outcome::proved, 10},
                               Known{"7/5,7/5,0; 7/5,0,7/5; 0,7/5,7/5", "1", Outcome::refuted, 0}}) {
        const Basis<Rational> basis = parse_basis(known.basis);
        const Rational p = parse_rational(known.p);
        const auto reference = check_exact_lattice(basis, p, field);
        REQUIRE(reference.verdict == known.verdict);
        REQUIRE(reference.contacts() == known.contacts);
        for (int trial = 0; trial < 4; ++trial) {
            const Transform u = trial < 2 ? random_unimodular(random, 3, 12) : random_unimodular(random, 1000, 3);
            const Basis<Rational> changed = times(u, basis);
            INFO(known.basis << " changed to " << basis_text(changed));
            const auto check = check_exact_lattice(changed, p, field);
            CHECK(check.verdict == known.verdict);
            CHECK(check.contacts() == known.contacts);
            // The same contact vectors: c in the changed basis is c U in the original one.
            std::set<Coefficients> original;
            for (const Coefficients& c : check.contact_vectors) original.insert(given_coefficients(c, u));
            CHECK(original == with_signs(reference.contact_vectors));
            if (known.verdict == Outcome::refuted) {
                REQUIRE(check.witness);
                CHECK(meets(check.witness->norm, "1.979898987322333068322364213893577309997540625527727"));  // 7/5 sqrt 2
            }
        }
    }
}

// The family lattices have interval bases (no exact reduction): a unimodular change with small
// entries keeps the coefficient box small, and the verdict and the contacts of the identities
// (mapped back through the change) are the same.
TEMPLATE_TEST_CASE("C0 at p = 2 after a unimodular change of basis: a packing with the same 12 contacts", "", Binary64, Arb128) {
    const TestType field;
    using I = typename TestType::Interval;
    const Rational p(2);
    const auto lattice = enclose_family(Family::C0, p, field);
    REQUIRE(lattice.basis);
    std::mt19937 random(12);
    const std::vector<Coefficients> identities = family_contact_triples(Family::C0);
    for (int trial = 0; trial < 3; ++trial) {
        const Transform u = random_unimodular(random, 1, 2);
        Basis<I> changed = *lattice.basis;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                changed[i][j] = field.integer(u[i][0]) * (*lattice.basis)[0][j] + field.integer(u[i][1]) * (*lattice.basis)[1][j] +
                                field.integer(u[i][2]) * (*lattice.basis)[2][j];
        const auto check = check_lattice(changed, field.rational(p), [&](const Coefficients& c) {
            const Coefficients original = representative(given_coefficients(c, u));
            return std::find(identities.begin(), identities.end(), original) != identities.end();
        });
        CHECK(check.verdict == Outcome::proved);
        CHECK(check.contacts() == 12);
    }
}

TEST_CASE("certificates of the flat and the skewed basis verify; a tampered reduction is rejected") {
    using Document = nlohmann::json;
    using superpack_checker::Verdict;
    using superpack_checker::verify_document;
    auto certificate = [](const std::string& basis_text, const std::string& p_text) {
        const Basis<Rational> basis = parse_basis(basis_text);
        const Rational p = parse_rational(p_text);
        const auto check = check_exact_lattice(basis, p, DoubleField{});
        return Document::parse(lattice_certificate(check, basis, p, DoubleField{}, 15).dump());
    };
    const Document skewed = certificate("2,0,0; 2000,2,0; 0,0,2", "2");
    CHECK(verify_document(skewed).verdict == Verdict::valid);
    CHECK(skewed["claim"]["data"]["contacts"] == 6);
    const Document flat = certificate("2,0,0; 0,2,0; 0,0,0.001", "2");
    CHECK(verify_document(flat).verdict == Verdict::valid);
    CHECK(flat["claim"]["data"]["witness"]["coefficients"] == Document::array({0, 0, 1}));
    CHECK(verify_document(certificate("2,0,0; 2000,2,0; 0,0,2", "1000000")).verdict == Verdict::valid);

    Document wrong_transform = skewed;
    wrong_transform["proof"]["reduction"]["transform"][0][0] = 2;
    CHECK(rejected_at(wrong_transform) == "proof.reduction.transform");
    Document wrong_basis = skewed;
    wrong_basis["proof"]["reduction"]["reduced_basis"][0][0] = "3";
    CHECK(rejected_at(wrong_basis) == "proof.reduction.reduced_basis");
    // Two rows of U and of R swapped: still a valid reduction, but the listed candidates are the
    // triples of the other order.
    Document swapped = skewed;
    std::swap(swapped["proof"]["reduction"]["transform"][0], swapped["proof"]["reduction"]["transform"][1]);
    std::swap(swapped["proof"]["reduction"]["reduced_basis"][0], swapped["proof"]["reduction"]["reduced_basis"][1]);
    CHECK(verify_document(swapped).verdict == Verdict::invalid);
}
