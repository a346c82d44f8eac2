// Concave superdisks (NOTES.md 13.8): the plane lattice checked as the space lattice with rows
// (u, 0), (w, 0), (0, 0, 2); the diamond lattice a packing and its shrink not; the search's
// certified lattice denser than the diamond insertion at three p, checked against sampled
// points in binary64 apart from the library, and the same in Arb; the command line.
#include <cmath>
#include <random>

#include "cli_run.hpp"
#include "superpack/problems/star/star_disk.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

PlaneBasis scaled(const PlaneBasis& b, const Rational& t) { return {{{b[0][0] * t, b[0][1] * t}, {b[1][0] * t, b[1][1] * t}}}; }

double g(double x, double y, double q) { return std::pow(std::fabs(x), q) + std::pow(std::fabs(y), q); }

// No sampled point of K lies inside K + v for the lattice vectors v with coefficients up to 6:
// the least g(x - v) over the points of K sampled.
double least_sampled(const PlaneBasis& b, double p) {
    const double q = 2 * p;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-1, 1);
    double least = HUGE_VAL;
    for (int n = 0; n < 30000;) {
        const double x = coordinate(random), y = coordinate(random);
        // Points near the axes: the arms hold most of the contacts.
        const double sx = random() % 2 ? x : x * x * x * x, sy = random() % 2 ? y : y * y * y * y;
        if (g(sx, sy, q) >= 1) continue;
        ++n;
        for (long a = -6; a <= 6; ++a)
            for (long c = -6; c <= 6; ++c) {
                if (a == 0 && c == 0) continue;
                const double vx = a * b[0][0].get_d() + c * b[1][0].get_d(), vy = a * b[0][1].get_d() + c * b[1][1].get_d();
                if (std::fabs(vx) < 2 && std::fabs(vy) < 2) least = std::min(least, g(sx - vx, sy - vy, q));
            }
    }
    return least;
}

const PlaneBasis diamond{{{1, 1}, {1, -1}}};

}  // namespace

TEST_CASE("the diamond lattice packs the concave superdisk (the tips touch); shrunk by 1/100 it overlaps, with a witness inside both disks") {
    const Binary64 field;
    const Rational p(3, 10);
    CHECK(check_plane_star_lattice(diamond, p, field).verdict == Outcome::proved);
    // The sampling of the next test can see an overlap: the diamond lattice shrunk by 1/10.
    CHECK(least_sampled(scaled(diamond, Rational(9, 10)), 0.3) < 1);
    const auto shrunk = check_plane_star_lattice(scaled(diamond, Rational(99, 100)), p, field);
    REQUIRE(shrunk.verdict == Outcome::refuted);
    REQUIRE(shrunk.witness_point);
    REQUIRE(shrunk.witness);
    // The witness in binary64, from the point's plane coordinates (setting z to 0 keeps it inside).
    const auto& point = shrunk.witness_point->point;
    const double x = mid_double(point[0]), y = mid_double(point[1]);
    const auto& c = shrunk.witness->coefficients;
    const PlaneBasis b = scaled(diamond, Rational(99, 100));
    const double vx = c[0] * b[0][0].get_d() + c[1] * b[1][0].get_d(), vy = c[0] * b[0][1].get_d() + c[1] * b[1][1].get_d();
    CHECK(c[2] == 0);
    CHECK(g(x, y, 0.6) < 1);
    CHECK(g(x - vx, y - vy, 0.6) < 1);
}

TEST_CASE("the concave superdisk's best certified lattice: denser than the diamond insertion, apart on sampled points, the same in Arb") {
    const Binary64 field;
    for (const Rational& p : {Rational(1, 5), Rational(3, 10), Rational(9, 20)}) {
        INFO("p = " << p);
        const auto best = best_star_disk_lattice(p, field);
        REQUIRE(best.status == Outcome::proved);
        REQUIRE(best.phi);
        CHECK(certainly_positive(*best.phi - best.insertion_phi));
        CHECK(certainly_less(*best.phi, field.integer(1)));
        CHECK(least_sampled(best.basis, p.get_d()) >= 1);
        // Scaled down by 1e-6 the lattice overlaps: it is critical to that order.
        CHECK(check_plane_star_lattice(scaled(best.basis, Rational(999999, 1000000)), p, field).verdict == Outcome::refuted);
    }
    const auto binary = best_star_disk_lattice(Rational(3, 10), field);
    const auto arb = best_star_disk_lattice(Rational(3, 10), Arb128{});
    REQUIRE(arb.phi);
    CHECK(overlaps(as_ball(*binary.phi), *arb.phi));
    const auto& area = golden()["superdisk_areas"][0];  // mpmath (scripts/make_golden.py)
    REQUIRE(area["p"] == "0.3");
    CHECK(meets(arb.area, area["area"].get<std::string>()));
    CHECK(meets(arb.insertion_phi * Arb128{}.integer(2), area["area"].get<std::string>()));  // A / 2
    CHECK_THROWS_AS(best_star_disk_lattice(Rational(1, 2), field), InputError);
}

TEST_CASE("superdisk --p below 1/2 prints the certified lattice, the insertion and no optimality claim") {
    const Run json = run("superdisk --p 0.3 --json");
    INFO(json.err);
    REQUIRE(json.status == 0);
    const auto document = nlohmann::json::parse(json.out);
    const auto& lattice = document["concave_lattice"];
    CHECK(lattice["status"] == "certified");
    CHECK(lattice["basis"].size() == 2);
    CHECK(lattice["optimality"].get<std::string>().find("convex") != std::string::npos);
    CHECK(std::stod(lattice["phi"]["lo"].get<std::string>()) > std::stod(lattice["diamond_insertion_phi"]["hi"].get<std::string>()));
    const Run table = run("superdisk --p 0.3");
    CHECK(table.status == 0);
    CHECK(table.out.find("certified lattice") != std::string::npos);
    CHECK(run("superdisk --p 0.3 --certificate /tmp/never.json").status == 2);
}
