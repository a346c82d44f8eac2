#include "crossover_reference.hpp"
#include "superpack/problems/crossover/crossover.hpp"

using namespace superpack;
using namespace superpack::test;

TEMPLATE_TEST_CASE("slopes at p = 1: certified a_-, a_+ and the paper's closed forms", "", Binary64, Arb128) {
    const TestType field;
    const auto slopes = certify_sphere_slopes(field);
    REQUIRE(slopes.a_minus);
    REQUIRE(slopes.a_plus);
    CHECK(width_upper(*slopes.a_minus) <= 1e-12);
    CHECK(width_upper(*slopes.a_plus) <= 1e-12);
    const auto& reference = crossover_reference()["slopes"];
    CHECK(meets(*slopes.a_minus, reference["O0"]["1"].template get<std::string>()));
    CHECK(meets(*slopes.a_plus, reference["C0"]["1"].template get<std::string>()));
    CHECK(slopes.a_plus_family == "C0");
    CHECK(meets(*slopes.c1.slope, reference["C1"]["1"].template get<std::string>()));
    // The closed forms, evaluated with the rigorous digamma, against mpmath.
    CHECK(meets(*slopes.closed_minus, reference_text("closed_a_minus")));
    CHECK(meets(*slopes.closed_plus, reference_text("closed_a_plus")));
    // a_-: the paper's closed form and its printed -0.02941... agree with the certified slope.
    CHECK(slopes.minus_vs_closed == Outcome::proved);
    CHECK(slopes.minus_printed.truncated == Outcome::proved);
    // a_+: the closed form (-2.606...) and the printed 0.3555... both disagree with the
    // certified slope 0.12366..., and with each other.
    CHECK(slopes.plus_vs_closed == Outcome::refuted);
    CHECK(slopes.plus_printed.truncated == Outcome::refuted);
    CHECK(slopes.plus_printed.rounded == Outcome::refuted);
    CHECK(slopes.closed_plus_printed.truncated == Outcome::refuted);
}

TEST_CASE("slopes at two precisions overlap") {
    const auto coarse = certify_sphere_slopes(BallField{128});
    const auto fine = certify_sphere_slopes(BallField{400});
    CHECK(overlaps(*coarse.a_minus, *fine.a_minus));
    CHECK(overlaps(*coarse.a_plus, *fine.a_plus));
    CHECK(width_upper(*fine.a_plus) < 1e-100);
}
