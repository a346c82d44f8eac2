// The exact contact test ||v||_(2p) = 2 (NOTES.md 5.3): decided from the structure of v where it
// can be, by exact integers otherwise, and without huge numbers at large 2p.
#include "superpack/geometry/exact_norm.hpp"
#include "superpack/problems/families/family_lattice_check.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

ExactNorm decide(const std::string& a, const std::string& b, const std::string& c, const std::string& p) {
    return decide_norm_is_two({parse_rational(a), parse_rational(b), parse_rational(c)}, parse_rational(p)).answer;
}

}  // namespace

TEST_CASE("exact norm 2: sums of powers that are 1 in rationals, with distinct coordinates") {
    CHECK(decide("6/5", "8/5", "0", "1") == ExactNorm::two);                 // 3^2 + 4^2 = 5^2
    CHECK(decide("6/5", "8/5", "1/1000000000", "1") == ExactNorm::not_two);
    CHECK(decide("1", "4/3", "5/3", "3/2") == ExactNorm::two);               // 3^3 + 4^3 + 5^3 = 6^3
    CHECK(decide("1", "4/3", "-5/3", "3/2") == ExactNorm::two);
    // Frye (1988): 95800^4 + 217519^4 + 414560^4 = 422481^4.
    CHECK(decide("191600/422481", "435038/422481", "829120/422481", "2") == ExactNorm::two);
    CHECK(decide("191601/422481", "435038/422481", "829120/422481", "2") == ExactNorm::not_two);
    CHECK(decide("1", "1", "0", "1/2") == ExactNorm::two);                   // 1/2 + 1/2 = 1
}

TEST_CASE("exact norm 2 for a non-integer 2p: only n-th powers can sum to 1") {
    // 2p = 3/2: a_i = (1/2)^2, (2/3)^2, (5/6)^2 give a_i^(3/2) = 3^3/6^3, 4^3/6^3, 5^3/6^3.
    CHECK(decide("1/2", "8/9", "25/18", "3/4") == ExactNorm::two);
    CHECK(decide("1/2", "8/9", "25/18001", "3/4") == ExactNorm::not_two);
    CHECK(decide("1", "1", "0", "3/4") == ExactNorm::not_two);  // 2 (1/2)^(3/2) is irrational
    CHECK(decide("2", "0", "0", "3/4") == ExactNorm::two);
    CHECK(decide("0", "-2", "0", "1000000.1") == ExactNorm::two);  // 2p = 10000001/5
    CHECK(decide("2", "1/3", "0", "1000000.1") == ExactNorm::not_two);
}

TEST_CASE("exact norm 2 at 2p = 2 * 10^6 and beyond, without forming huge powers") {
    // A coordinate of size 2 decides alone; so does one above 2, and a lone one below 2.
    CHECK(decide("2", "0", "0", "1000000") == ExactNorm::two);
    CHECK(decide("-2", "1/10000000000", "0", "1000000") == ExactNorm::not_two);
    CHECK(decide("2.0000000001", "0", "0", "1000000") == ExactNorm::not_two);
    CHECK(decide("1.9999999999", "0", "0", "1000000000000") == ExactNorm::not_two);
    // Two coordinates below 2 whose powers sum to 1 within 10^-27: decided unequal modulo a prime
    // (the exact powers would have ~10^8 bits, beyond the budget).
    const auto near = decide_norm_is_two({parse_rational("1.99999999999999999998"),
                                          parse_rational("1.9999684572046182437"), Rational(0)},
                                         Rational(1000000));
    CHECK(near.answer == ExactNorm::not_two);
    CHECK(near.reason.find("modulo") != std::string::npos);
}

// Before, the exact test stopped at 2p <= 64: (2, 0, 0) at p = 10^6 was a near contact and the
// check undecided.
TEMPLATE_TEST_CASE("2Z^3 at p = 10^6 and p = 10^6 + 1/10: 6 contacts, decided exactly", "", Binary64, Arb128) {
    const TestType field;
    for (const char* p_text : {"1000000", "1000000.1"}) {
        INFO("p = " << p_text);
        const auto check = check_exact_lattice(parse_basis("2,0,0; 0,2,0; 0,0,2"), parse_rational(p_text), field);
        CHECK(check.verdict == Outcome::proved);
        CHECK(check.contacts() == 6);
    }
}
