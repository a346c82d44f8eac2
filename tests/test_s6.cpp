// The family S6, superpack's six-pair lattice of (p*_o, 1) (NOTES.md 4.2): against mpmath
// (scripts/make_s6_golden.py -> tests/data/s6.json) in both backends, exactly its six contact
// pairs, the certified gap to O0, `best` naming it, and the domain refusals on the command line.
#include <algorithm>
#include <set>

#include "cli_run.hpp"
#include "superpack/problems/best/best.hpp"
#include "superpack/problems/families/family_lattice_check.hpp"
#include "superpack/problems/families/s6_definition.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

TEST_CASE("S6 against mpmath at p = 0.8, 0.85, 0.9, 0.95, 0.99: binary64 and Arb 30 digits contain it and overlap") {
    const DoubleField binary64;
    const BallField thirty{bits_for_digits(30)};
    REQUIRE(s6_golden().size() == 5);
    for (const auto& entry : s6_golden()) {
        const std::string p_text = entry["p"];
        INFO("S6 at p = " << p_text);
        const Rational p = parse_rational(p_text);
        const auto low = enclose_family(Family::S6, p, binary64);
        REQUIRE(low.status == Outcome::proved);
        const auto high = enclose_family(Family::S6, p, thirty);
        REQUIRE(high.status == Outcome::proved);
        CHECK(meets(*low.phi, entry["phi"]));
        CHECK(meets(*high.phi, entry["phi"]));
        CHECK(overlaps(as_ball(*low.phi), *high.phi));
        // Krawczyk stops at 2^12 units of the last place: 1e-13 to 5e-12 in binary64 (NOTES 4.2).
        CHECK(width_upper(*low.phi) < 1e-11);
        CHECK(width_upper(*high.phi) < 1e-28);
        REQUIRE(low.parameters.size() == 15);
        for (int k = 0; k < 9; ++k) {
            const std::string& b = entry["basis"][k / 3][k % 3];
            CHECK(low.parameters[static_cast<std::size_t>(k)].name == "b" + std::to_string(k / 3) + std::to_string(k % 3));
            CHECK(meets((*low.basis)[k / 3][k % 3], b));
            CHECK(meets((*high.basis)[k / 3][k % 3], b));
        }
        for (std::size_t i = 0; i < 6; ++i) {
            CHECK(low.parameters[9 + i].name == "mu" + std::to_string(i + 1));
            CHECK(meets(low.parameters[9 + i].value, entry["multipliers"][i]));
            CHECK(certainly_positive(low.parameters[9 + i].value));
        }
        CHECK(certainly_positive(*low.determinant));
    }
}

TEST_CASE("S6 is a packing with exactly its six contact pairs, and beats O0 at p = 9/10 by a certified gap") {
    const DoubleField field;
    const Rational p(9, 10);
    const auto s6 = enclose_family(Family::S6, p, field);
    REQUIRE(s6.status == Outcome::proved);
    const auto check = check_family_lattice(s6, field.rational(p));
    REQUIRE(check.verdict == Outcome::proved);
    CHECK(check.contacts() == 12);
    CHECK(claimed_contacts(Family::S6) == 12);
    std::set<Coefficients> expected, found(check.contact_vectors.begin(), check.contact_vectors.end());
    for (const Coefficients& c : s6_contact_triples()) {
        expected.insert(c);
        expected.insert({-c[0], -c[1], -c[2]});
    }
    CHECK(found == expected);
    // Minkowski's six pairs b1, b2, b3, b2 - b3, b3 - b1, b1 - b2 (up to sign).
    CHECK(s6_contact_triples() == std::vector<Coefficients>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, -1}, {1, 0, -1}, {1, -1, 0}});
    const auto o0 = enclose_family(Family::O0, p, field);
    REQUIRE(o0.status == Outcome::proved);
    REQUIRE(check_family_lattice(o0, field.rational(p)).verdict == Outcome::proved);
    const DInterval gap = *s6.phi - *o0.phi;
    CHECK(certainly_less(field.rational(Rational(1769, 1000000)), gap));  // 1.7693652e-3 (NOTES 4.2)
}

TEST_CASE("best at p = 9/10 names S6: the search lattice coincides with it and is not certainly denser") {
    BestOptions options;
    options.search.random_starts = 4;
    const BestLattice<DInterval> best = find_best_lattice(Rational(9, 10), DoubleField{}, options);
    REQUIRE(best.status == Outcome::proved);
    CHECK(best.source == BestSource::family);
    CHECK(best_name(best) == "S6");
    REQUIRE(best.local);
    CHECK(best.local->verdict == Outcome::proved);
}

TEST_CASE("S6 on the command line: outside ln3/ln4 < p < 1 exit 2, next to p*_o exit 4, an audit range must hold 9/10") {
    struct Case {
        const char* arguments;
        int status;
        const char* needle;
    };
    const Case cases[] = {
        {"density --family S6 --p 0.79", 2, "outside the domain of S6 (ln3/ln4 < p < 1)"},
        {"density --family S6 --p 1", 2, "outside the domain of S6"},
        {"density --family S6 --p 1/2", 2, "outside the domain of S6"},
        {"check-lattice --family S6 --p 0.79", 2, "outside the domain of S6"},
        // 0.792481250360578 < p*_o = 0.79248125036057809...: decided at 256 bits, refused.
        {"density --family S6 --p 0.792481250360578", 2, "outside the domain of S6"},
        // Above p*_o by 1e-17: binary64 cannot separate p from its enclosure of ln3/ln4.
        {"density --family S6 --p 0.79248125036057811", 4, "not certainly above p*_o"},
        {"audit --family S6 --p-range 0.95:0.99", 2, "must hold p = 9/10"},
        {"audit --family S6 --p-range 0.79:0.9", 2, "outside the domain of S6"},
        {"density --family S6 --p 0.9", 0, ""},
    };
    for (const Case& c : cases) {
        INFO(c.arguments);
        const Run result = run(c.arguments);
        INFO(result.err);
        CHECK(result.status == c.status);
        CHECK(result.err.find(c.needle) != std::string::npos);
    }
}
