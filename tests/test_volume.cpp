#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

TEMPLATE_TEST_CASE("superball volume against the mpmath Beta form", "", Binary64, Arb128, Arb400) {
    const TestType field;
    for (const auto& entry : golden()["families"]) {
        const Rational p = parse_rational(entry["p"].get<std::string>());
        const auto volume = enclose_superball_volume(p, field);
        INFO(entry["family"].get<std::string>() << " p = " << entry["p"].get<std::string>());
        CHECK(meets(volume, entry["volume"].get<std::string>()));
        CHECK(width_upper(volume) < width_budget(field) * 8);
    }
}

TEMPLATE_TEST_CASE("volume and area identities", "", Binary64, Arb128, Arb400) {
    const TestType field;
    const auto pi = field.pi();
    // Octahedron |x|+|y|+|z| <= 1 has volume 4/3; the unit ball 4 pi / 3; the disk pi; the square |x|+|y| <= 1 area 2.
    CHECK(contains(enclose_superball_volume(Rational(1, 2), field), field.rational(Rational(4, 3))));
    CHECK(overlaps(enclose_superball_volume(Rational(1), field), pi * field.integer(4) / field.integer(3)));
    CHECK(overlaps(enclose_superdisk_area(Rational(1), field), pi));
    CHECK(contains(enclose_superdisk_area(Rational(1, 2), field), field.integer(2)));
    // The cube limit: V(p) < 8 and increasing towards it.
    CHECK(certainly_less(enclose_superball_volume(Rational(5), field), enclose_superball_volume(Rational(10), field)));
    CHECK(certainly_less(enclose_superball_volume(Rational(10), field), field.integer(8)));
}

TEMPLATE_TEST_CASE("superdisk area against mpmath", "", Binary64, Arb128) {
    const TestType field;
    for (const auto& entry : golden()["superdisk_areas"]) {
        INFO("p = " << entry["p"].get<std::string>());
        CHECK(meets(enclose_superdisk_area(parse_rational(entry["p"].get<std::string>()), field),
                    entry["area"].get<std::string>()));
    }
}

TEST_CASE("the paper's Beta form (Eq. 4) and the Gamma form agree at 400 bits") {
    const BallField field{400};
    for (const Rational& p : {Rational(1, 2), Rational(3, 4), Rational(1), Rational(23, 20), Rational(7, 2)}) {
        const Ball P = field.rational(p);
        const Ball one = field.integer(1), two = field.integer(2);
        auto beta = [](const Ball& a, const Ball& b) { return gamma(a) * gamma(b) / gamma(a + b); };
        const Ball a = one / (two * P);
        const Ball paper = two / (P * P) * beta(a, (two * P + one) / (two * P)) * beta(a, (P + one) / P);
        INFO("p = " << p.get_str());
        CHECK(overlaps(paper, enclose_superball_volume(p, field)));
    }
}

TEST_CASE("volume derivative in p (Jet) agrees with a difference quotient") {
    const BallField field{200};
    const Ball p = field.rational(Rational(3, 2));
    const Jet<Ball> volume = enclose_ball_volume(variable(p), 3);
    const Ball h = field.rational(Rational(1, 1000000000));
    const Ball quotient = (enclose_ball_volume(p + h, 3) - enclose_ball_volume(p - h, 3)) / (field.integer(2) * h);
    // Central difference error ~ h^2 V''' / 6 < 1e-15 here.
    CHECK(certainly_less(abs(volume.derivative - quotient), field.rational(Rational(1, 1000000000000000))));
}
