// The superball as a body: convexity, membership, gauge, support function and support point,
// against mpmath's Lagrange maximisation (scripts/make_body_reference.py) and identities.
#include <random>

#include "superpack/geometry/body.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

const nlohmann::json& body_reference() {
    static const nlohmann::json data = [] {
        std::ifstream file(std::string(SUPERPACK_TEST_DATA) + "/body.json");
        REQUIRE(file.good());
        return nlohmann::json::parse(file);
    }();
    return data;
}

template <class Field>
std::vector<typename Field::Interval> vector_of(const std::vector<Rational>& values, const Field& field) {
    std::vector<typename Field::Interval> result;
    for (const Rational& value : values) result.push_back(field.rational(value));
    return result;
}

template <class I>
I dot(const std::vector<I>& a, const std::vector<I>& b) {
    I sum = a[0] * b[0];
    for (std::size_t i = 1; i < a.size(); ++i) sum = sum + a[i] * b[i];
    return sum;
}

}  // namespace

TEST_CASE("convexity and the domain of a superball") {
    CHECK(make_superball(3, Rational(1, 2)).convex());
    CHECK(make_superball(3, Rational(3, 2)).convex());
    CHECK_FALSE(make_superball(3, Rational(49, 100)).convex());
    CHECK(make_superball(2, Rational(3, 2)).dual_exponent() == Rational(3, 2));
    CHECK(make_superball(3, Rational(1)).dual_exponent() == 2);
    CHECK_THROWS_AS(make_superball(4, Rational(1)), InputError);
    CHECK_THROWS_AS(make_superball(3, Rational(0)), InputError);
    CHECK_THROWS_AS(make_superball(3, Rational(1, 2)).dual_exponent(), std::domain_error);
}

TEMPLATE_TEST_CASE("membership is three-valued and exact on the boundary", "", Binary64, Arb128) {
    const TestType field;
    const Superball ball = make_superball(3, Rational(3, 2));
    // e1 lies on the boundary: in K, not in its interior. The enclosure of |1|^3 need not be
    // the point 1, so either answer may be undecided, but neither may be wrong.
    const auto e1 = vector_of({1, 0, 0}, field);
    CHECK(in_body(ball, e1) != Outcome::refuted);
    CHECK(in_interior(ball, e1) != Outcome::proved);
    CHECK(in_interior(ball, vector_of({Rational(1, 2), Rational(1, 2), Rational(1, 2)}, field)) == Outcome::proved);
    CHECK(in_body(ball, vector_of({Rational(9, 10), Rational(9, 10), 0}, field)) == Outcome::refuted);
    // A box that straddles the boundary cannot be decided.
    const std::vector<typename TestType::Interval> straddle{hull(field.rational(Rational(9, 10)), field.rational(Rational(11, 10))),
                                                             field.integer(0), field.integer(0)};
    CHECK(in_body(ball, straddle) == Outcome::undecided);
    CHECK(in_interior(ball, straddle) == Outcome::undecided);
    // A concave superball (p = 1/4) contains (9/10, 0, 0) and misses (1/2, 1/2, 0).
    const Superball cross = make_superball(3, Rational(1, 4));
    CHECK(in_interior(cross, vector_of({Rational(9, 10), 0, 0}, field)) == Outcome::proved);
    CHECK(in_body(cross, vector_of({Rational(1, 2), Rational(1, 2), 0}, field)) == Outcome::refuted);
}

TEMPLATE_TEST_CASE("the gauge is homogeneous and 1 on the boundary", "", Binary64, Arb128) {
    const TestType field;
    for (const Rational& p : {Rational(1, 4), Rational(1, 2), Rational(1), Rational(23, 20), Rational(7)}) {
        const Superball ball = make_superball(3, p);
        INFO("p = " << p.get_str());
        CHECK(contains(gauge(ball, vector_of({0, -1, 0}, field)), field.integer(1)));
        const auto x = vector_of({Rational(1, 3), Rational(-2, 5), Rational(3, 7)}, field);
        const auto scaled = vector_of({Rational(5, 3), Rational(-2), Rational(15, 7)}, field);
        CHECK(overlaps(gauge(ball, scaled), field.integer(5) * gauge(ball, x)));
    }
}

TEMPLATE_TEST_CASE("support function against mpmath's Lagrange maximisation", "", Binary64, Arb128, Arb400) {
    const TestType field;
    for (const auto& row : body_reference()["support"]) {
        std::vector<Rational> u;
        for (const auto& c : row["u"]) u.push_back(parse_rational(c.get<std::string>()));
        const Superball ball = make_superball(static_cast<int>(u.size()), parse_rational(row["p"].get<std::string>()));
        const auto h = support_function(ball, vector_of(u, field));
        INFO("p = " << row["p"] << ", u = " << row["u"]);
        CHECK(meets(h, row["support"].get<std::string>()));
        CHECK(width_upper(h) < width_budget(field) * 64);
    }
}

TEMPLATE_TEST_CASE("support function: closed cases and the support point", "", Binary64, Arb128) {
    const TestType field;
    const auto u = vector_of({Rational(1), Rational(-2), Rational(2)}, field);
    // The Euclidean ball: |u| = 3; the octahedron and every concave superball: max |u_i| = 2.
    CHECK(contains(support_function(make_superball(3, Rational(1)), u), field.integer(3)));
    CHECK(contains(support_function(make_superball(3, Rational(1, 2)), u), field.integer(2)));
    CHECK(contains(support_function(make_superball(3, Rational(1, 5)), u), field.integer(2)));
    CHECK_THROWS_AS(support_point(make_superball(3, Rational(1, 2)), u), std::domain_error);
    for (const Rational& p : {Rational(3, 4), Rational(23, 20), Rational(5), Rational(100)}) {
        const Superball ball = make_superball(3, p);
        INFO("p = " << p.get_str());
        const auto x = support_point(ball, u);
        CHECK(overlaps(gauge_power(x, field.rational(2 * p)), field.integer(1)));
        CHECK(overlaps(dot(u, x), support_function(ball, u)));
    }
}

TEMPLATE_TEST_CASE("no boundary point beats the support function (Hoelder)", "", Binary64, Arb128) {
    const TestType field;
    std::mt19937_64 random(20261201);
    std::uniform_int_distribution<int> numerator(-50, 50);
    for (const Rational& p : {Rational(1, 4), Rational(1, 2), Rational(3, 4), Rational(3, 2), Rational(20)}) {
        const Superball ball = make_superball(3, p);
        for (int k = 0; k < 200; ++k) {
            std::vector<Rational> y, w;
            for (int i = 0; i < 3; ++i) {
                y.push_back(Rational(numerator(random), 7));
                w.push_back(Rational(numerator(random), 11));
            }
            if (y == std::vector<Rational>(3, Rational(0))) continue;
            const auto u = vector_of(w, field);
            const auto raw = vector_of(y, field);
            const auto norm = gauge(ball, raw);
            std::vector<typename TestType::Interval> x;
            for (const auto& yi : raw) x.push_back(yi / norm);  // on the boundary of K
            INFO("p = " << p.get_str() << ", k = " << k);
            CHECK_FALSE(certainly_less(support_function(ball, u), dot(u, x)));
        }
    }
}
