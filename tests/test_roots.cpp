// Newton and Krawczyk against roots known in closed form, and the statuses they must not give.
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

TEMPLATE_TEST_CASE("interval Newton isolates sqrt(2) and contains it", "", Binary64, Arb128, Arb400) {
    const TestType field;
    // The example on which Arb 2.23's arb_calc_newton_step can claim success and miss.
    auto f = [&](const auto& x) { return x * x - field.integer(2); };
    for (const auto& box : {hull(field.integer(1), field.integer(2)), from_doubles(field.integer(0), 1.4, 1.5),
                            from_doubles(field.integer(0), 1.41421356, 1.41421357)}) {
        const NewtonResult<typename TestType::Interval> result = newton_isolate(f, box, 0.0, 100);
        CHECK(result.status == RootStatus::unique);
        CHECK(result.existence);
        CHECK(result.uniqueness);
        CHECK(meets(result.box, "1.4142135623730950488016887242096980785696718753769"));
        CHECK(width_upper(result.box) < width_budget(field));
    }
}

TEMPLATE_TEST_CASE("interval Newton: no root, and a double root is never unique", "", Binary64, Arb128) {
    const TestType field;
    auto f = [&](const auto& x) { return x * x - field.integer(2); };
    CHECK(newton_isolate(f, hull(field.integer(2), field.integer(3)), 0.0, 50).status == RootStatus::none);
    // x^2 - 1/4 has two roots in [-1, 1]: the derivative vanishes, so undecided.
    auto g = [&](const auto& x) { return x * x - field.rational(Rational(1, 4)); };
    const auto two_roots = newton_isolate(g, hull(field.integer(-1), field.integer(1)), 0.0, 50);
    CHECK(two_roots.status == RootStatus::undecided);
    CHECK(!two_roots.uniqueness);
    // (x - 1)^2 has a double root: never `unique`.
    auto h = [&](const auto& x) { return (x - field.integer(1)) * (x - field.integer(1)); };
    CHECK(newton_isolate(h, from_doubles(field.integer(0), 0.9, 1.1), 0.0, 50).status != RootStatus::unique);
}

TEMPLATE_TEST_CASE("Krawczyk on the circle and the diagonal: (1/sqrt2, 1/sqrt2)", "", Binary64, Arb128, Arb400) {
    const TestType field;
    using I = typename TestType::Interval;
    auto f = [&](const auto& x) {
        using S = std::decay_t<decltype(x[0])>;
        return std::vector<S>{x[0] * x[0] + x[1] * x[1] - field.integer(1), x[0] - x[1]};
    };
    const std::vector<I> box{from_doubles(field.integer(0), 0.6, 0.8), from_doubles(field.integer(0), 0.65, 0.75)};
    const KrawczykResult<I> result = krawczyk_isolate(f, box, 0.0, 60);
    REQUIRE(result.status == RootStatus::unique);
    for (const I& coordinate : result.box)
        CHECK(meets(coordinate, "0.70710678118654752440084436210484903928483593768847"));
    // A box holding both roots (+-1/sqrt2) must not be called unique; a box with none is none.
    const std::vector<I> both{hull(field.integer(-1), field.integer(1)), hull(field.integer(-1), field.integer(1))};
    CHECK(krawczyk_isolate(f, both, 0.0, 60).status != RootStatus::unique);
    const std::vector<I> empty{from_doubles(field.integer(0), 0.1, 0.2), from_doubles(field.integer(0), 0.1, 0.2)};
    CHECK(krawczyk_isolate(f, empty, 0.0, 60).status == RootStatus::none);
}

TEMPLATE_TEST_CASE("branch and bound finds both roots and accounts for every piece", "", Binary64, Arb128) {
    const TestType field;
    using I = typename TestType::Interval;
    auto f = [&](const auto& x) {
        using S = std::decay_t<decltype(x[0])>;
        return std::vector<S>{x[0] * x[0] + x[1] * x[1] - field.integer(1), x[0] - x[1]};
    };
    const std::vector<I> box{hull(field.rational(Rational(-9, 8)), field.integer(1)), hull(field.integer(-1), field.integer(1))};
    const auto leaves = isolate_roots(f, box, 1e-9, 10000, 0.0);
    int unique = 0, undecided = 0;
    for (const auto& leaf : leaves) {
        unique += leaf.status == RootStatus::unique;
        undecided += leaf.status == RootStatus::undecided;
    }
    CHECK(unique == 2);
    CHECK(undecided == 0);
    // A budget too small leaves pieces undecided, never dropped.
    const auto starved = isolate_roots(f, box, 1e-9, 1, 0.0);
    int starved_undecided = 0;
    for (const auto& leaf : starved) starved_undecided += leaf.status == RootStatus::undecided;
    CHECK(starved_undecided > 0);
}
