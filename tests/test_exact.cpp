#include "support.hpp"

using superpack::InputError;
using superpack::parse_rational;
using superpack::Rational;

TEST_CASE("decimal strings and fractions are read exactly") {
    CHECK(parse_rational("1.15") == Rational(23, 20));
    CHECK(parse_rational("3/2") == Rational(3, 2));
    CHECK(parse_rational("-0.5") == Rational(-1, 2));
    CHECK(parse_rational(".25") == Rational(1, 4));
    CHECK(parse_rational("2e-3") == Rational(1, 500));
    CHECK(parse_rational("1.5E2") == Rational(150));
    CHECK(parse_rational("0.1") != Rational(0.1));  // the double 0.1 is not 1/10
    CHECK(parse_rational("4/6") == Rational(2, 3));
    CHECK(parse_rational("1.5/0.5") == Rational(3));
}

TEST_CASE("malformed numbers are rejected with the text named") {
    for (const char* bad : {"abc", "", "1..2", "1/0", "1e", "--1", "1.2.3", "0x10", "1/"}) {
        INFO(bad);
        CHECK_THROWS_AS(parse_rational(bad), InputError);
    }
    CHECK_THROWS_WITH(parse_rational("abc"), Catch::Contains("abc"));
}

TEST_CASE("exact values print as decimals when they terminate") {
    CHECK(superpack::decimal_or_fraction_text(Rational(23, 20)) == "1.15");
    CHECK(superpack::decimal_or_fraction_text(Rational(1, 3)) == "1/3");
    CHECK(superpack::decimal_or_fraction_text(Rational(-1, 8)) == "-0.125");
    CHECK(superpack::rational_text(Rational(6, 4)) == "3/2");
}
