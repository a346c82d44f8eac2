// Both interval backends run the same test bodies.
#include "superpack/arith/self_test.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

TEST_CASE("the rounding self-test passes on this machine") {
    const SelfTestReport report = run_rounding_self_test();
    INFO((report.failures.empty() ? std::string() : report.failures.front()));
    CHECK(report.passed);
    CHECK(report.checks >= 8);
}

TEMPLATE_TEST_CASE("rationals are enclosed, not rounded", "", Binary64, Arb128, Arb400) {
    const TestType field;
    const auto third = field.rational(Rational(1, 3));
    CHECK(meets(third, "0.33333333333333333333333333333333333333333333333333"));
    CHECK(!certainly_less(third, third));
    CHECK(width_upper(third) > 0);
    CHECK(width_upper(third) < width_budget(field));
    CHECK(width_upper(field.rational(Rational(3, 2))) == 0);  // dyadic: exact
}

TEMPLATE_TEST_CASE("x^y is exp(y log x) with rigorous bounds, including x = 0", "", Binary64, Arb128, Arb400) {
    const TestType field;
    const auto two = field.integer(2);
    const auto y = field.rational(Rational(3, 2));
    CHECK(meets(pow_nonneg(two, y), "2.8284271247461900976033774484193961571393437507539"));  // 2^(3/2)
    CHECK(width_upper(pow_nonneg(two, y)) < width_budget(field));
    // 0^y = 0 for y > 0; [0, b]^y = [0, b^y].
    const auto zero_power = pow_nonneg(field.integer(0), y);
    CHECK(width_upper(zero_power) == 0);
    CHECK(contains_zero(zero_power));
    const auto range = pow_nonneg(hull(field.integer(0), field.integer(4)), y);
    CHECK(contains(range, field.integer(0)));
    CHECK(contains(range, field.integer(8)));
    CHECK(!contains(range, field.integer(9)));
    // 0^0 = 1 (the limit used by derivatives at p = 1/2), and a negative base is refused.
    CHECK(contains(pow_nonneg(field.integer(0), field.integer(0)), field.integer(1)));
    CHECK_THROWS_AS(pow_nonneg(field.integer(-1), y), std::domain_error);
    // Inclusion monotonicity: a point inside the argument maps inside the image.
    const auto wide = pow_nonneg(hull(field.integer(1), field.integer(3)), hull(y, field.integer(2)));
    CHECK(contains(wide, pow_nonneg(field.integer(2), y)));
    CHECK(contains(wide, field.integer(9)));
}

TEMPLATE_TEST_CASE("|x|^y and sign(x)|x|^y straddling zero", "", Binary64, Arb128) {
    const TestType field;
    const auto x = hull(field.integer(-2), field.integer(1));
    const auto y = field.integer(2);
    const auto magnitude = pow_abs(x, y);
    CHECK(certainly_nonnegative(magnitude));
    CHECK(contains(magnitude, field.integer(4)));
    CHECK(contains(magnitude, field.integer(0)));
    const auto signed_power = pow_signed(x, y);
    CHECK(contains(signed_power, field.integer(-4)));
    CHECK(contains(signed_power, field.integer(4)));
}

TEMPLATE_TEST_CASE("Gamma over point and wide arguments", "", Binary64, Arb128, Arb400) {
    const TestType field;
    // Gamma(1/2) = sqrt(pi); Gamma(1/3) from mpmath.
    CHECK(meets(gamma(field.rational(Rational(1, 2))), "1.7724538509055160272981674833411451827975494561224"));
    CHECK(meets(gamma(field.rational(Rational(1, 3))), "2.6789385347077476336556929409746776441286893779573"));
    CHECK(width_upper(gamma(field.rational(Rational(1, 3)))) < width_budget(field));
    // A wide argument across the minimum of Gamma (x0 = 1.4616...) keeps the minimum inside.
    const auto across = gamma(hull(field.integer(1), field.integer(2)));
    CHECK(meets(across, "0.88560319441088870027881590058258873320795153366990"));
    CHECK(contains(across, field.integer(1)));
    // A monotone piece is evaluated at its endpoints: the hull is tight.
    const auto falling = gamma(hull(field.rational(Rational(1, 4)), field.rational(Rational(1, 2))));
    CHECK(width_upper(falling) < 1.86);  // Gamma(1/4) - Gamma(1/2) = 1.8530...
    CHECK_THROWS_AS(gamma(hull(field.integer(-1), field.integer(1))), std::domain_error);
}

TEMPLATE_TEST_CASE("two precisions overlap on random arguments", "", Binary64, Arb128) {
    const TestType field;
    const BallField fine{300};
    for (int k = 1; k <= 200; ++k) {
        const Rational x(k * 37 % 997 + 1, 97), y(k % 13 + 1, 7);
        INFO("x = " << x.get_str() << ", y = " << y.get_str());
        CHECK(overlaps(as_ball(pow_nonneg(field.rational(x), field.rational(y))),
                      pow_nonneg(fine.rational(x), fine.rational(y))));
        CHECK(overlaps(as_ball(gamma(field.rational(x))), gamma(fine.rational(x))));
    }
}
