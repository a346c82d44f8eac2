// Certificates of kind "periodic-packing" (checker/claims/claim_periodic_packing.cpp, NOTES.md 14): N
// rotated superballs repeated by a lattice, each close pair separated by a plane. Documents built
// here from exact rationals (touching balls in 2Z^3, two touching superballs at p = 2 in 4Z^3,
// rotated ones by 90 and about 53 degrees) verify and say what was verified; a missing pair, a
// normal that does not separate (also after the cell shrinks), p < 1/2, a radius below the
// circumradius, a singular cell, a zero quaternion and inputs that disagree are rejected at the
// step they break; pairs not in canonical form, out of range or twice, and a cell too thin for
// the enumeration are unreadable; every normal of a touching configuration turned, and every
// required pair deleted, is rejected. The producer's certificates (`simulate`) verify too.
#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <array>
#include <string>
#include <vector>

#include "checker/core/render.hpp"
#include "checker/verifier.hpp"
#include "superpack/cert/periodic_certificate.hpp"
#include "superpack/problems/periodic/periodic_packing.hpp"
#include "support.hpp"
#include "tamper.hpp"

using superpack_checker::Verdict;
using superpack_checker::verify_document;
using Document = nlohmann::json;
using superpack::test::rejected_at;

namespace {

using Q = mpq_class;
using Vec = std::array<Q, 3>;
using Quat = std::array<Q, 4>;

const Quat identity{1, 0, 0, 0};
const Quat quarter_turn{1, 0, 0, 1};  // 90 degrees about z, unnormalised: R e_x = e_y
const Quat turned{2, 0, 0, 1};        // R = (1/5) [[3, -4, 0], [4, 3, 0], [0, 0, 5]], about 53 degrees

struct Configuration {
    Q p;
    std::array<Vec, 3> cell;
    std::vector<Vec> centers;
    std::vector<Quat> quaternions;
    Q radius;
};

std::string text(const Q& q) { return q.get_str(); }

template <std::size_t n>
Document rationals(const std::array<Q, n>& values) {
    Document result = Document::array();
    for (const Q& x : values) result.push_back(text(x));
    return result;
}

bool lexicographically_positive(const std::array<long, 3>& k) {
    for (long x : k)
        if (x != 0) return x > 0;
    return false;
}

// The close pairs by the claim's rule, in a box of shifts large enough for these cells, each
// with the centre line d as its normal (it separates exactly when |d| >= h(R_i^T e) + h(R_j^T e),
// e = d / |d|, which holds for every pair below).
Document close_pairs(const Configuration& c, long box = 3) {
    Document pairs = Document::array();
    for (std::size_t i = 0; i < c.centers.size(); ++i)
        for (std::size_t j = i; j < c.centers.size(); ++j)
            for (long a = -box; a <= box; ++a)
                for (long b = -box; b <= box; ++b)
                    for (long e = -box; e <= box; ++e) {
                        const std::array<long, 3> k{a, b, e};
                        if (i == j && !lexicographically_positive(k)) continue;
                        Vec d;
                        for (int m = 0; m < 3; ++m)
                            d[m] = c.centers[j][m] - c.centers[i][m] + a * c.cell[0][m] + b * c.cell[1][m] + e * c.cell[2][m];
                        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] >= 4 * c.radius * c.radius) continue;
                        pairs.push_back(Document{{"first", i}, {"second", j}, {"shift", {a, b, e}}, {"normal", rationals(d)}});
                    }
    return pairs;
}

// The head every certificate has (a binary64 one at 15 digits), the claim and the inputs; the
// text is the checker's rendering once everything else passes.
Document document(const Configuration& c, const Document& pairs) {
    Document cell = Document::array(), particles = Document::array();
    for (const Vec& row : c.cell) cell.push_back(rationals(row));
    for (std::size_t i = 0; i < c.centers.size(); ++i)
        particles.push_back(Document{{"center", rationals(c.centers[i])}, {"quaternion", rationals(c.quaternions[i])}});
    Document result{{"format", "superpack-certificate"},
                    {"format_version", 2},
                    {"tool", "superpack"},
                    {"version", "0.1.0"},
                    {"commit", "test"},
                    {"command", "simulate"},
                    {"backend", "binary64-interval (test document)"},
                    {"bits", 53},
                    {"digits", 15},
                    {"rounding_self_test", {{"passed", true}, {"checks", 19}}}};
    result["claim"] = Document{{"kind", "periodic-packing"},
                               {"text", ""},
                               {"data", {{"p", text(c.p)}, {"cell", cell}, {"particles", particles}, {"packing", true}}}};
    result["inputs"] = Document{{"p", text(c.p)}, {"p_decimal", superpack_checker::exact_text(c.p)}, {"particles", c.centers.size()}};
    result["proof"] = Document{{"kind", "separating-planes"}, {"radius", text(c.radius)}, {"pairs", pairs}};
    const auto report = verify_document(result);
    if (report.verdict == Verdict::invalid && report.path == "claim.text") result["claim"]["text"] = report.rendered_claim;
    return result;
}

Document document(const Configuration& c) { return document(c, close_pairs(c)); }

std::array<Vec, 3> cubic(const Q& side) { return {{{side, 0, 0}, {0, side, 0}, {0, 0, side}}}; }

// (a) one ball in 2Z^3, touching its six neighbours; r = 1, so no pair is closer than 2r.
Configuration balls() { return {1, cubic(2), {{0, 0, 0}}, {identity}, 1}; }
// (b) two superballs at p = 2 in 4Z^3 touching face to face along x; r = 33/25 >= 3^(1/4).
Configuration superballs(const Quat& second = identity) { return {2, cubic(4), {{0, 0, 0}, {2, 0, 0}}, {identity, second}, Q(33, 25)}; }
// (c) the second one turned by about 53 degrees about z: its extent along x is
// ||(3/5, -4/5, 0)||_(4/3) = 1.1815..., apart from its neighbours at 12/5 and 13/5.
Configuration rotated() {
    return {2, {{{5, 0, 0}, {0, 4, 0}, {0, 0, 4}}}, {{0, 0, 0}, {Q(12, 5), 0, 0}}, {identity, turned}, Q(33, 25)};
}

std::string sentence(const Document& d) { return verify_document(d).rendered_claim; }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The path of a malformed (unreadable) verdict, or "(not malformed)".
std::string malformed_at(const Document& d) {
    const auto report = verify_document(d);
    return report.verdict == Verdict::malformed ? report.path : "(not malformed)";
}

Document axis_pairs() {
    Document pairs = Document::array();
    for (int m = 0; m < 3; ++m) {
        Document shift = {0, 0, 0}, normal = {"0", "0", "0"};
        shift[m] = 1;
        normal[m] = "1";
        pairs.push_back(Document{{"first", 0}, {"second", 0}, {"shift", shift}, {"normal", normal}});
    }
    return pairs;
}

}  // namespace

TEST_CASE("periodic-packing: touching balls, superballs and rotated ones verify and say what was verified") {
    // (a) No pair is closer than 2r = 2: the empty list is complete; the touching axis pairs,
    // listed besides, are verified too.
    const Document none = document(balls());
    CHECK(none["proof"]["pairs"].empty());
    CHECK(verify_document(none).verdict == Verdict::valid);
    const Document axes = document(balls(), axis_pairs());
    CHECK(verify_document(axes).verdict == Verdict::valid);
    CHECK(contains(sentence(axes), "is a packing"));
    CHECK(contains(sentence(axes), "of packing density N V_sb(p) / |det B| with |det B| = 8."));
    CHECK(contains(sentence(axes), "N = 1 superball c_i + R(q_i) K"));
    CHECK(contains(sentence(axes), "basis rows (2, 0, 0), (0, 2, 0), (0, 0, 2)"));
    CHECK(contains(sentence(axes), "0 such pairs"));
    // At r = 3/2 the six neighbours and the twelve face diagonals (2 sqrt 2 < 3) are close; the
    // body diagonals (2 sqrt 3) are not. Up to translation: 3 + 6 pairs.
    Configuration wide = balls();
    wide.radius = Q(3, 2);
    const Document nine = document(wide);
    CHECK(nine["proof"]["pairs"].size() == 9);
    CHECK(verify_document(nine).verdict == Verdict::valid);
    CHECK(contains(sentence(nine), "9 such pairs up to translation"));

    // (b) Touching faces: the pair and its image through the cell.
    const Document two = document(superballs());
    CHECK(two["proof"]["pairs"].size() == 2);
    const auto report = verify_document(two);
    INFO(report.path << ": " << report.message);
    CHECK(report.verdict == Verdict::valid);
    CHECK(contains(sentence(two), "N = 2 superballs"));
    CHECK(contains(sentence(two), "c_1 = (2, 0, 0), q_1 = (1, 0, 0, 0)"));
    CHECK(contains(sentence(two), "r = 1.32 >= the circumradius of K"));
    CHECK(contains(sentence(two), "|det B| = 64."));
    CHECK(contains(sentence(two), "2 such pairs"));

    // The superball at p = 2 is symmetric under the quarter turn: still touching, exactly.
    const Document quarter = document(superballs(quarter_turn));
    CHECK(verify_document(quarter).verdict == Verdict::valid);
    CHECK(contains(sentence(quarter), "q_1 = (1, 0, 0, 1)"));
    // (c) A general rational rotation, apart (the sums of support functions in MPFI).
    const Document general = document(rotated());
    CHECK(general["proof"]["pairs"].size() == 2);
    CHECK(verify_document(general).verdict == Verdict::valid);
    CHECK(contains(sentence(general), "|det B| = 80."));
    // ... but not at centre distance 2.1 < 1 + 1.1815...: the plane along x does not separate.
    Configuration close = rotated();
    close.centers[1] = {Q(21, 10), 0, 0};
    close.cell[0] = {Q(42, 10), 0, 0};
    CHECK(rejected_at(document(close)) == "proof.pairs[0].normal");

    // An octahedron (p = 1/2, h = max |u_l|, exact), and p = 3/4 (s = 3, the sum of integer
    // powers exact): the turned body's extent along x is ||(3/5, -4/5, 0)||_3 = 0.8996..., so
    // centres 1.95 apart (closer than 2r = 2) are separated, 1.85 apart not.
    CHECK(verify_document(document({Q(1, 2), cubic(2), {{0, 0, 0}}, {identity}, 1}, axis_pairs())).verdict == Verdict::valid);
    Configuration three_quarters{Q(3, 4), {{{Q(39, 10), 0, 0}, {0, 4, 0}, {0, 0, 4}}}, {{0, 0, 0}, {Q(39, 20), 0, 0}}, {identity, turned}, 1};
    const Document apart = document(three_quarters);
    CHECK(apart["proof"]["pairs"].size() == 2);
    CHECK(verify_document(apart).verdict == Verdict::valid);
    three_quarters.centers[1] = {Q(37, 20), 0, 0};
    three_quarters.cell[0] = {Q(37, 10), 0, 0};
    CHECK(rejected_at(document(three_quarters)) == "proof.pairs[0].normal");
}

TEST_CASE("periodic-packing: each broken step is rejected where it breaks") {
    const Document original = document(superballs());
    REQUIRE(verify_document(original).verdict == Verdict::valid);
    for (std::size_t k = 0; k < original["proof"]["pairs"].size(); ++k) {
        Document missing = original;
        missing["proof"]["pairs"].erase(k);
        INFO("pair " << k);
        CHECK(rejected_at(missing) == "proof.pairs");
        CHECK(contains(verify_document(missing).message, "is missing"));
    }
    Document wrong = original;
    wrong["proof"]["pairs"][0]["normal"] = {"0", "1", "0"};
    CHECK(rejected_at(wrong) == "proof.pairs[0].normal");
    Document zero = original;
    zero["proof"]["pairs"][1]["normal"] = {"0", "0", "0"};
    CHECK(rejected_at(zero) == "proof.pairs[1].normal");
    // The cell shrunk to 3Z^3: the image at distance 1 (pairs[0], shift (-1, 0, 0)) overlaps,
    // and its plane cannot separate.
    REQUIRE(original["proof"]["pairs"][0]["shift"] == Document({-1, 0, 0}));
    Document shrunk = original;
    shrunk["claim"]["data"]["cell"] = {{"3", "0", "0"}, {"0", "3", "0"}, {"0", "0", "3"}};
    CHECK(rejected_at(shrunk) == "proof.pairs[0].normal");
    // The same centre twice: d = 0, which no plane separates.
    Configuration doubled = superballs();
    doubled.centers[1] = {0, 0, 0};
    CHECK(rejected_at(document(doubled)) == "proof.pairs[0].normal");
    // An extra pair, not needed, is verified as well.
    Document extra = document(balls(), axis_pairs());
    extra["proof"]["pairs"][2]["normal"] = {"1", "0", "0"};
    CHECK(rejected_at(extra) == "proof.pairs[2].normal");

    Document concave = original;
    concave["claim"]["data"]["p"] = concave["inputs"]["p"] = "1/3";
    CHECK(rejected_at(concave) == "claim.data.p");
    Document p_input = original;
    p_input["inputs"]["p"] = "3";
    CHECK(rejected_at(p_input) == "inputs.p");
    Document p_decimal = original;
    p_decimal["inputs"]["p_decimal"] = "2.0";
    CHECK(rejected_at(p_decimal) == "inputs.p_decimal");
    Document small = original;
    small["proof"]["radius"] = "1";  // 1 < 3^(1/4)
    CHECK(rejected_at(small) == "proof.radius");
    Document tiny = document(balls(), axis_pairs());
    tiny["proof"]["radius"] = "99/100";
    CHECK(rejected_at(tiny) == "proof.radius");
    Document singular = original;
    singular["claim"]["data"]["cell"] = {{"4", "0", "0"}, {"0", "4", "0"}, {"4", "4", "0"}};
    CHECK(rejected_at(singular) == "claim.data.cell");
    Document no_rotation = original;
    no_rotation["claim"]["data"]["particles"][1]["quaternion"] = {"0", "0", "0", "0"};
    CHECK(rejected_at(no_rotation) == "claim.data.particles[1].quaternion");
    Document count = original;
    count["inputs"]["particles"] = 3;
    CHECK(rejected_at(count) == "inputs.particles");
    Document not_packing = original;
    not_packing["claim"]["data"]["packing"] = false;
    CHECK(rejected_at(not_packing) == "claim.data.packing");
    Document text = original;
    text["claim"]["text"] = "A packing.";
    CHECK(rejected_at(text) == "claim.text");
    Document unknown = original;
    unknown["proof"]["pairs"][0]["gap"] = "1";
    CHECK(rejected_at(unknown) == "proof.pairs[0].gap");
}

TEST_CASE("periodic-packing: pairs out of canonical form, out of range or twice, and too thin a cell, are unreadable") {
    const Document original = document(superballs());
    Document reversed = original;
    reversed["proof"]["pairs"][0]["first"] = 1;
    reversed["proof"]["pairs"][0]["second"] = 0;
    CHECK(malformed_at(reversed) == "proof.pairs[0]");
    Document range = original;
    range["proof"]["pairs"][0]["second"] = 2;
    CHECK(malformed_at(range) == "proof.pairs[0].second");
    Document twice = original;
    twice["proof"]["pairs"].push_back(twice["proof"]["pairs"][0]);
    CHECK(malformed_at(twice) == "proof.pairs[2]");
    Document negative = document(balls(), axis_pairs());
    negative["proof"]["pairs"][0]["shift"] = {-1, 0, 0};
    CHECK(malformed_at(negative) == "proof.pairs[0].shift");
    Document self = document(balls(), axis_pairs());
    self["proof"]["pairs"][0]["shift"] = {0, 0, 0};
    CHECK(malformed_at(self) == "proof.pairs[0].shift");
    Document kind = original;
    kind["proof"]["kind"] = "enumeration";
    CHECK(malformed_at(kind) == "proof.kind");
    Document empty = original;
    empty["claim"]["data"]["particles"] = Document::array();
    CHECK(malformed_at(empty) == "claim.data.particles");
    Document many = original;
    for (int i = 0; i < 255; ++i) many["claim"]["data"]["particles"].push_back(many["claim"]["data"]["particles"][0]);
    CHECK(malformed_at(many) == "claim.data.particles");  // 257 > max_periodic_particles
    // 1/100 Z^3 at r = 1: 401^3 shifts in the box, refused before any is enumerated.
    Document thin = document(balls());
    thin["claim"]["data"]["cell"] = {{"1/100", "0", "0"}, {"0", "1/100", "0"}, {"0", "0", "1/100"}};
    const auto refused = verify_document(thin);
    CHECK(refused.verdict == Verdict::malformed);
    CHECK(refused.path == "claim.data.cell");
    CHECK(contains(refused.message, "max_periodic_shifts"));
}

TEST_CASE("periodic-packing: every normal of a touching configuration turned, and every required pair deleted, is rejected") {
    for (const Document& original : {document(superballs()), document(superballs(quarter_turn))}) {
        REQUIRE(verify_document(original).verdict == Verdict::valid);
        const Document& pairs = original["proof"]["pairs"];
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            // Across the centre line (along it the normal only scales, which changes nothing).
            for (int m = 1; m < 3; ++m)
                for (const char* step : {"1/1000", "-1/1000"}) {
                    Document moved = original;
                    Document& entry = moved["proof"]["pairs"][k]["normal"][m];
                    entry = Q(Q(entry.get<std::string>()) + Q(step)).get_str();
                    INFO("pair " << k << ", normal entry " << m << " moved by " << step);
                    CHECK(rejected_at(moved) == "proof.pairs[" + std::to_string(k) + "].normal");
                }
            Document deleted = original;
            deleted["proof"]["pairs"].erase(k);
            CHECK(rejected_at(deleted) == "proof.pairs");
        }
        // A centre moved towards its neighbour, in the claim and nothing else: the pair with
        // shift 0 (pairs[1]) overlaps.
        Document moved = original;
        moved["claim"]["data"]["particles"][1]["center"][0] = "1999/1000";
        CHECK(rejected_at(moved) == "proof.pairs[1].normal");
    }
}

TEST_CASE("periodic-packing: the producer's certificates verify") {
    using namespace superpack;
    PeriodicPacking packing;
    packing.p = 2;
    packing.cell = {{{4, 0, 0}, {0, 4, 0}, {0, 0, 4}}};
    packing.centers = {{0, 0, 0}, {2, 0, 0}};
    packing.quaternions = {{1, 0, 0, 0}, {1, 0, 0, 1}};
    const auto proved = certify_periodic_packing(packing, {}, DoubleField{});
    REQUIRE(proved.status == Outcome::proved);
    const Document written = Document::parse(periodic_certificate(proved, DoubleField{}, 15, "simulate").dump());
    const auto report = verify_document(written);
    INFO(report.path << ": " << report.message);
    CHECK(report.verdict == Verdict::valid);
    CHECK(written["claim"]["kind"] == "periodic-packing");
    CHECK(contains(written["claim"]["text"].get<std::string>(), "is a packing"));
    // Overlapping balls, scaled apart by the producer, in Arb.
    PeriodicPacking balls;
    balls.p = 1;
    balls.cell = {{{Rational(19, 10), 0, 0}, {0, 2, 0}, {1, 1, 2}}};
    balls.centers = {{0, 0, 0}};
    balls.quaternions = {{Rational(3, 7), Rational(-2, 5), Rational(1, 3), Rational(5, 11)}};
    const BallField arb{82};
    const auto scaled = certify_periodic_packing(balls, {}, arb);
    REQUIRE(scaled.status == Outcome::proved);
    CHECK(verify_document(Document::parse(periodic_certificate(scaled, arb, 15, "simulate").dump())).verdict == Verdict::valid);
}
