// The generic subdivision engines of solve/: the depth-first partition and the best-first
// minimiser, on problems whose answers are known exactly.
#include "superpack/solve/minimise.hpp"
#include "superpack/solve/partition.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

struct SignLeaf {
    DInterval x;
    int sign;  // -1, +1, or 0 when given up on
    std::string reason;
};

}  // namespace

TEST_CASE("partition: the leaves cover the domain left to right, and nothing is dropped") {
    const DoubleField field;
    // The sign of x^2 - 2 on [0, 2]: decided everywhere but near sqrt 2.
    auto classify = [](const std::vector<DInterval>& box) -> Classification<SignLeaf> {
        const DInterval value = square(box[0]) - DInterval(2.0);
        if (certainly_negative(value)) return decided(SignLeaf{box[0], -1, ""});
        if (certainly_positive(value)) return decided(SignLeaf{box[0], 1, ""});
        return not_decided<SignLeaf>("x^2 - 2 may vanish");
    };
    auto give_up = [](const std::vector<DInterval>& box, const std::string& reason) { return SignLeaf{box[0], 0, reason}; };
    for (const double min_width : {1e-3, 1e-12}) {
        const std::vector<SignLeaf> leaves =
            partition(std::vector<std::vector<DInterval>>{{hull(field.integer(0), field.integer(1))},
                                                          {hull(field.integer(1), field.integer(2))}},
                      classify, give_up, SubdivisionLimits{min_width, 10000});
        INFO("min_width " << min_width);
        REQUIRE(!leaves.empty());
        CHECK(leaves.front().x.lower() == 0);
        CHECK(leaves.back().x.upper() == 2);
        int undecided = 0;
        for (std::size_t k = 0; k < leaves.size(); ++k) {
            if (k > 0) CHECK(leaves[k].x.lower() == leaves[k - 1].x.upper());  // no gap, no overlap
            if (leaves[k].sign == 0) {
                ++undecided;
                CHECK(contains(leaves[k].x, DInterval(1.4142135623730951)));
                CHECK(leaves[k].reason == "x^2 - 2 may vanish; subdivision budget reached");
            } else {
                CHECK((leaves[k].sign < 0) == (leaves[k].x.upper() < 1.4142135623730951));
            }
        }
        CHECK(undecided >= 1);
        CHECK(undecided <= 2);
    }
    // A budget of 5 pieces: the leaves still cover [0, 2], the rest given up on.
    const std::vector<SignLeaf> few =
        partition(std::vector<std::vector<DInterval>>{{hull(field.integer(0), field.integer(2))}}, classify, give_up,
                  SubdivisionLimits{0, 5});
    CHECK(few.size() <= 5);
    CHECK(few.front().x.lower() == 0);
    CHECK(few.back().x.upper() == 2);
    for (std::size_t k = 1; k < few.size(); ++k) CHECK(few[k].x.lower() == few[k - 1].x.upper());
}

TEMPLATE_TEST_CASE("minimise: a quadratic in two dimensions with its exact minimum", "", Binary64, Arb128) {
    using I = typename TestType::Interval;
    const TestType field;
    // f(x, y) = (x - 1/3)^2 + 2 (y + 1/4)^2 + 1 on [-1, 1]^2: minimum 1 at (1/3, -1/4).
    const I third = field.rational(Rational(1, 3)), quarter = field.rational(Rational(1, 4)), one = field.integer(1);
    auto f = [&](const std::vector<I>& x) { return square(x[0] - third) + field.integer(2) * square(x[1] + quarter) + one; };
    // The best value handed to bound is a certified value of f, so never below the minimum 1.
    int calls_with_best = 0;
    bool best_below_minimum = false;
    auto bound = [&](const std::vector<I>& box, const std::optional<I>& best) {
        if (best) {
            ++calls_with_best;
            best_below_minimum = best_below_minimum || certainly_less(upper_point(*best), one);
        }
        return BoundedBox<I, int>{box, true, f(box), 0, "natural extension"};
    };
    auto value = [&](const std::vector<I>& point) { return std::optional<PointValue<I, std::vector<I>>>({f(point), point}); };
    MinimiseOptions options;
    options.relative_tolerance = 1e-6;
    options.max_pieces = 4000;
    const std::vector<I> domain{hull(-one, one), hull(-one, one)};
    const auto minimum = minimise<I, int, std::vector<I>>(domain, bound, value, std::nullopt, options);
    REQUIRE(minimum.certified);
    REQUIRE(minimum.lowest);
    CHECK(contains(*minimum.lowest, one));
    CHECK(width_upper(*minimum.lowest) < 1e-5);
    bool minimiser_kept = false;
    double area = 0;
    for (const auto& leaf : minimum.leaves) {
        area += width_upper(leaf.box[0]) * width_upper(leaf.box[1]);
        const bool holds = contains(leaf.box[0], third) && contains(leaf.box[1], -quarter);
        if (holds) CHECK(leaf.fate == LeafFate::candidate);  // the minimiser is never discarded
        minimiser_kept = minimiser_kept || holds;
        if (leaf.fate == LeafFate::discarded)
            CHECK(certainly_less(upper_point(minimum.best->value), lower_point(leaf.lower)));
    }
    CHECK(minimiser_kept);
    CHECK(calls_with_best > 0);
    CHECK_FALSE(best_below_minimum);
    // The leaves partition the domain (a ball holds its radius to 30 bits, hence the slack).
    CHECK(area == Approx(4.0).epsilon(1e-6));
}

TEST_CASE("minimise: a region without a bound makes the minimum undecided, and is kept") {
    using I = DInterval;
    const DoubleField field;
    auto f = [](const std::vector<I>& x) { return square(x[0]); };
    // No bound where x > 1/2: those boxes are bisected down to the width limit, then kept.
    auto bound = [&](const std::vector<I>& box, const std::optional<I>&) {
        const bool bounded = box[0].upper() <= 0.5;
        return BoundedBox<I, int>{box, bounded, f(box), 0, bounded ? "natural extension" : "no bound here"};
    };
    auto value = [&](const std::vector<I>& point) { return std::optional<PointValue<I, int>>({f(point), 0}); };
    MinimiseOptions options;
    options.min_undecided_width = 1e-3;
    const auto minimum =
        minimise<I, int, int>({hull(field.integer(0), field.integer(1))}, bound, value, std::nullopt, options);
    CHECK_FALSE(minimum.certified);
    int undecided = 0;
    for (const auto& leaf : minimum.leaves) undecided += leaf.fate == LeafFate::undecided;
    CHECK(undecided > 0);
}
