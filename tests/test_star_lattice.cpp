// check-lattice below p = 1/2 (the star-body check, NOTES.md 13.2): Minkowski's lattice and its
// shrunk copies on both sides of the first contact, a lattice that the gauge test would pass but
// whose translates overlap, contacts at the tips, and the command line. Every witness point is
// re-evaluated here in binary64 from the exact basis, apart from the library's arithmetic.
#include <cmath>
#include <random>
#include <sstream>

#include "cli_run.hpp"
#include "superpack/geometry/lattice.hpp"
#include "superpack/problems/families/family_lattice_check.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

const Rational p_cross(3, 10);
const std::string minkowski = "2/3,2/3,-2/3; -1/3,4/3,-1/3; 1/3,-1/3,-4/3";

// The basis "text" with every entry multiplied by t.
std::string scaled(const std::string& text, const Rational& t) {
    const Basis<Rational> basis = parse_basis(text);
    std::string out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out += Rational(basis[i][j] * t).get_str() + (j < 2 ? "," : i < 2 ? "; " : "");
    return out;
}

double g(const std::array<double, 3>& x) {
    double sum = 0;
    for (double xi : x) sum += std::pow(std::fabs(xi), 2 * p_cross.get_d());
    return sum;
}

// The witness vector rebuilt from the exact basis and its coefficients, in binary64.
std::array<double, 3> witness_vector(const std::string& text, const Coefficients& c) {
    const Basis<Rational> basis = parse_basis(text);
    std::array<double, 3> v{};
    for (int j = 0; j < 3; ++j) v[j] = Rational(c[0] * basis[0][j] + c[1] * basis[1][j] + c[2] * basis[2][j]).get_d();
    return v;
}

// A refuted check's witness point: inside K and inside K + v, by a plain binary64 evaluation
// (its rounding error, below 1e-14, is far below the margin of the witnesses here, 2e-10 at the
// nearest contact).
void check_witness(const std::string& text, const LatticeCheck<DInterval>& check) {
    REQUIRE(check.witness);
    REQUIRE(check.witness_point);
    const std::array<double, 3> v = witness_vector(text, check.witness->coefficients);
    std::array<double, 3> x{}, shifted{};
    for (int j = 0; j < 3; ++j) {
        x[j] = mid_double(check.witness_point->point[j]);
        shifted[j] = x[j] - v[j];
    }
    INFO("x = (" << x[0] << ", " << x[1] << ", " << x[2] << "), v = (" << v[0] << ", " << v[1] << ", " << v[2] << ")");
    CHECK(g(x) < 1);
    CHECK(g(shifted) < 1);
    CHECK(certainly_less(check.witness_point->value, DInterval(1)));
    CHECK(certainly_less(check.witness_point->value_at_translate, DInterval(1)));
}

// For a proved packing: no sampled point of the cube lies in K and in K + v for any candidate v.
void check_sampled_disjoint(const LatticeCheck<DInterval>& check) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> coordinate(-1, 1);
    long inside = 0;
    for (int n = 0; n < 100000; ++n) {
        const std::array<double, 3> x{coordinate(random), coordinate(random), coordinate(random)};
        if (g(x) >= 1) continue;
        ++inside;
        for (const auto& candidate : check.evaluated) {
            std::array<double, 3> shifted{};
            for (int j = 0; j < 3; ++j) shifted[j] = x[j] - mid_double(candidate.vector[j]);
            CHECK(g(shifted) >= 1);
        }
    }
    CHECK(inside > 1000);  // the sample reaches into K
}

LatticeCheck<DInterval> check(const std::string& text) { return check_exact_lattice(parse_basis(text), p_cross, DoubleField{}); }

}  // namespace

TEST_CASE("Minkowski's lattice at p = 3/10 is a packing of the cross; scaled by 1/4 it overlaps at a certified point") {
    const auto packing = check(minkowski);
    CHECK(packing.verdict == Outcome::proved);
    CHECK(packing.near_contacts.empty());
    CHECK_FALSE(packing.witness_point);
    CHECK(packing.evaluated.size() > 13);
    check_sampled_disjoint(packing);
    const std::string quarter = scaled(minkowski, Rational(1, 4));
    const auto overlapping = check(quarter);
    CHECK(overlapping.verdict == Outcome::refuted);
    check_witness(quarter, overlapping);
}

TEST_CASE("a lattice whose vectors all have gauge above 2 overlaps: the gauge test would pass it") {
    // (9/10, 9/10, 0) has gauge 2.86 at p = 3/10, and K + v meets K at (0, 9/10, 0) (NOTES.md 13.1).
    const std::string text = "9/10,9/10,0; 9/5,-9/5,0; 0,0,21/10";
    const auto result = check(text);
    REQUIRE_FALSE(result.evaluated.empty());
    for (const auto& candidate : result.evaluated) CHECK(certainly_less(DInterval(2), candidate.norm));
    CHECK(result.verdict == Outcome::refuted);
    check_witness(text, result);
}

TEST_CASE("Minkowski's lattice shrunk towards its first contact: overlapping at t = 0.770475409, a packing at 0.77047541") {
    // Found by bisection of check-lattice (NOTES.md 13.2); the two lattices differ by 1.3e-9.
    const std::string below = scaled(minkowski, Rational(770475409, 1000000000));
    const auto before = check(below);
    CHECK(before.verdict == Outcome::refuted);
    check_witness(below, before);
    const auto after = check(scaled(minkowski, Rational(77047541, 100000000)));
    CHECK(after.verdict == Outcome::proved);
    check_sampled_disjoint(after);
}

TEST_CASE("tips: 2 Z^3 is a packing (the tips touch on the axes), and so is tip-to-tip off the axes") {
    CHECK(check("2,0,0; 0,2,0; 0,0,2").verdict == Outcome::proved);
    // (1, 1, 0): the tip (1, 0, 0) of K is the tip of K + v's arm along -y (NOTES.md 13.1): the
    // interiors are disjoint, which no box cover proves and the closed form does (13.5).
    const auto touching = check("1,1,0; 1,-1,0; 0,0,2");
    CHECK(touching.verdict == Outcome::proved);
    CHECK(touching.near_contacts.empty());
    check_sampled_disjoint(touching);
    CHECK(check("99/100,99/100,0; 99/100,-99/100,0; 0,0,2").verdict == Outcome::refuted);
    CHECK(check("101/100,101/100,0; 101/100,-101/100,0; 0,0,2").verdict == Outcome::proved);
}

TEST_CASE("check-lattice --p 0.3: JSON with the witness point, Arb agrees") {
    const Run packing = run("check-lattice --p 0.3 --basis '" + minkowski + "' --json");
    CHECK(packing.status == 0);
    const auto document = nlohmann::json::parse(packing.out);
    CHECK(document["verdict"] == "admissible");
    CHECK_FALSE(document.contains("witness_point"));
    const Run arb = run("check-lattice --p 0.3 --digits 40 --basis '" + minkowski + "' --json");
    CHECK(arb.status == 0);
    CHECK(nlohmann::json::parse(arb.out)["verdict"] == "admissible");
    const Run overlapping = run("check-lattice --p 3/10 --basis '" + scaled(minkowski, Rational(1, 4)) + "' --json");
    CHECK(overlapping.status == 0);
    const auto refuted = nlohmann::json::parse(overlapping.out);
    CHECK(refuted["verdict"] == "overlapping");
    CHECK(refuted["witness_point"]["point"].size() == 3);
    CHECK(refuted["witness_point"].contains("gauge_power_at_translate"));
    const Run table = run("check-lattice --p 0.3 --basis '" + scaled(minkowski, Rational(1, 4)) + "'");
    CHECK(table.out.find("both < 1") != std::string::npos);
    CHECK(table.out.find("not a packing density") != std::string::npos);  // V/|det| of an overlap
    CHECK(table.out.find("phi ") == std::string::npos);
    CHECK(run("check-lattice --p 0 --basis '" + minkowski + "'").status == 2);
}

TEST_CASE("family minkowski-insertion: phi = V(p) 27/38 (mpmath), a packing below 1/2 by the star test, 14 contacts at 1/2") {
    const Binary64 field;
    const auto at = [&](const Rational& p) { return enclose_family(Family::MinkowskiInsertion, p, field); };
    const auto lattice = at(Rational(3, 10));
    CHECK(check_family_lattice(lattice, Rational(3, 10)).verdict == Outcome::proved);
    CHECK(check_family_lattice(at(Rational(9, 20)), Rational(9, 20)).verdict == Outcome::proved);
    const auto octahedra = check_family_lattice(at(Rational(1, 2)), Rational(1, 2));
    CHECK(octahedra.verdict == Outcome::proved);
    CHECK(octahedra.contact_vectors.size() == 14);
    CHECK_THROWS_AS(at(Rational(3, 5)), InputError);
    CHECK_THROWS_AS(at(Rational(0)), InputError);
    const Run density = run("density --family minkowski-insertion --p 0.3 --json");
    CHECK(density.status == 0);
    CHECK(nlohmann::json::parse(density.out)["packing"]["verdict"] == "admissible");
    // No family claim for the insertion (check-lattice certifies its exact basis instead).
    const Run refused = run("density --family minkowski-insertion --p 0.3 --certificate /tmp/never.json --json");
    CHECK(refused.status == 2);
    CHECK(nlohmann::json::parse(refused.out)["error"].get<std::string>().find("check-lattice --family minkowski-insertion") !=
          std::string::npos);
    CHECK(run("audit --family minkowski-insertion").status == 2);
}

TEST_CASE("best --scan across 1/2: the insertion's columns, last in each row, enclose V(p) 27/38 (mpmath) where p <= 1/2") {
    const Run scan = run("best --scan 0.45:0.55:0.05 --starts 0 --csv");
    INFO(scan.err);
    REQUIRE(scan.status == 0);
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(scan.out);
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> fields;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
        if (line.back() == ',') fields.push_back("");
        REQUIRE(fields.size() >= 3);
        rows.push_back({fields.end() - 3, fields.end()});
    }
    REQUIRE(rows.size() == 4);
    CHECK(rows[0] == std::vector<std::string>{"minkowski-insertion_lo", "minkowski-insertion_hi", "minkowski-insertion_packing"});
    const auto encloses = [](const std::vector<std::string>& row, const std::string& phi) {
        return row[2] == "yes" && meets(hull(reference(row[0]), reference(row[1])), phi);
    };
    CHECK(encloses(rows[1], "0.71500508003315159757303438243295366830029485912929"));
    CHECK(encloses(rows[2], "0.94736842105263157894736842105263157894736842105263"));  // 18/19, the octahedra
    CHECK(rows[3] == std::vector<std::string>{"", "", "outside"});
    CHECK(scan.out.find("\n0.45,") != std::string::npos);
}
