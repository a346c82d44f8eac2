// Certificates of kind "star-lattice-check" (NOTES.md 13.5): check-lattice below p = 1/2. A packing
// (Minkowski's lattice at p = 3/10, the tips of 2Z^3 and the lattice of tips off the axes) and an
// overlap (Minkowski's lattice scaled by 1/4, a rational witness point) verify in both backends;
// a deleted candidate, a changed status, p, basis entry or witness point, and every bound moved
// inward are rejected at a named step; the checker's case test agrees with the producer's and
// with the box cover on random translations.
#include <filesystem>
#include <fstream>
#include <random>

#include "checker/formulas/star_cases.hpp"
#include "checker/verifier.hpp"
#include "cli_run.hpp"
#include "superpack/cert/star_lattice_certificate.hpp"
#include "superpack/geometry/star_cases.hpp"
#include "superpack/geometry/star_overlap.hpp"
#include "support.hpp"
#include "tamper.hpp"

using namespace superpack;
using namespace superpack::test;
using superpack_checker::Verdict;
using superpack_checker::verify_document;
using Document = nlohmann::json;

namespace {

const char* const minkowski = "2/3,2/3,-2/3; -1/3,4/3,-1/3; 1/3,-1/3,-4/3";
const char* const quarter = "1/6,1/6,-1/6; -1/12,1/3,-1/12; 1/12,-1/12,-1/3";  // Minkowski's times 1/4

// At 15 digits: binary64, or Arb balls of the 82 bits the checker expects for 15 digits.
template <class Field = DoubleField>
Document certificate(const std::string& p, const std::string& basis, const Field& field = Field{}) {
    const Rational exact = parse_rational(p);
    const Basis<Rational> rows = parse_basis(basis);
    const auto check = check_exact_lattice(rows, exact, field);
    return Document::parse(exact_lattice_certificate(check, rows, exact, field, 15).dump());
}

std::string sentence(const Document& document) { return verify_document(document).rendered_claim; }

}  // namespace

TEST_CASE("star-lattice-check: packings and an overlap verify in both backends and say what was verified") {
    const Document packing = certificate("3/10", minkowski);
    CHECK(packing["claim"]["kind"] == "star-lattice-check");
    CHECK(packing["claim"]["data"]["packing"] == true);
    CHECK(verify_document(packing).verdict == Verdict::valid);
    CHECK(sentence(packing).find("is a packing of the concave superball") != std::string::npos);
    CHECK(sentence(packing).find("|det B| = 38/27") != std::string::npos);
    CHECK(verify_document(certificate("3/10", minkowski, BallField{82})).verdict == Verdict::valid);
    // The tips touch: on the axes (2Z^3) and off them, tip against tip (NOTES.md 13.5).
    CHECK(verify_document(certificate("3/10", "2,0,0; 0,2,0; 0,0,2")).verdict == Verdict::valid);
    CHECK(verify_document(certificate("3/10", "1,1,0; 1,-1,0; 0,0,2")).verdict == Verdict::valid);
    CHECK(verify_document(certificate("1/10", minkowski)).verdict == Verdict::valid);

    const Document overlap = certificate("3/10", quarter);
    CHECK(overlap["claim"]["data"]["packing"] == false);
    CHECK(overlap["proof"]["kind"] == "witness-point");
    CHECK(verify_document(overlap).verdict == Verdict::valid);
    CHECK(sentence(overlap).find("is not a packing") != std::string::npos);
    CHECK(verify_document(certificate("3/10", quarter, BallField{82})).verdict == Verdict::valid);
    // The gauge test would pass this lattice (every vector has gauge > 2); its translates overlap.
    const Document gauge_passes = certificate("3/10", "9/10,9/10,0; 9/5,-9/5,0; 0,0,21/10");
    CHECK(gauge_passes["claim"]["data"]["packing"] == false);
    CHECK(verify_document(gauge_passes).verdict == Verdict::valid);
}

TEST_CASE("star-lattice-check: tampering is rejected at the step it breaks") {
    const Document original = certificate("3/10", minkowski);
    for (std::size_t k : {std::size_t{0}, original["proof"]["candidates"].size() / 2}) {
        Document deleted = original;
        deleted["proof"]["candidates"].erase(k);
        INFO("candidate " << k);
        CHECK(rejected_at(deleted) == "proof.candidates");
    }
    Document status = original;
    status["proof"]["candidates"][3]["status"] = "overlapping";
    CHECK(rejected_at(status) == "proof.candidates[3].status");
    Document convex = original;
    convex["inputs"]["p"] = convex["claim"]["data"]["p"] = "1/2";
    CHECK(rejected_at(convex) == "inputs.p");
    Document p_input = original;
    p_input["inputs"]["p"] = "1/5";
    CHECK(rejected_at(p_input) == "inputs.p");
    // The same lattice shrunk by 1/4 in claim and inputs: its translates overlap.
    Document shrunk = original;
    const Document small = certificate("3/10", quarter);
    shrunk["inputs"]["basis"] = shrunk["claim"]["data"]["basis"] = small["inputs"]["basis"];
    CHECK(rejected_at(shrunk).rfind("proof.", 0) == 0);
    Document lowered = original;
    lowered["proof"]["coefficient_bound"][0] = 1;
    CHECK(rejected_at(lowered) == "proof.coefficient_bound");

    const Document overlap = certificate("3/10", quarter);
    Document moved = overlap;
    moved["claim"]["data"]["witness"]["point"][0] = "1";  // outside K
    CHECK(rejected_at(moved).rfind("claim.data.witness", 0) == 0);
    Document other = overlap;
    other["claim"]["data"]["witness"]["coefficients"] = Document::array({0, 0, 5});
    CHECK(rejected_at(other).rfind("claim.data.witness", 0) == 0);
    Document claimed = overlap;
    claimed["claim"]["data"]["packing"] = true;
    CHECK(verify_document(claimed).verdict != Verdict::valid);
    for (const Document& document : {original, overlap}) {
        std::vector<std::string> bounds;
        collect_bounds(document["claim"], "/claim", bounds);
        collect_bounds(document["proof"], "/proof", bounds);
        REQUIRE(!bounds.empty());
        for (const std::string& bound : bounds) check_tampered_bound_rejected(document, bound);
    }
}

TEST_CASE("the checker's case test agrees with the producer's, and both with the box cover where it decides") {
    std::mt19937_64 random(14);
    std::uniform_int_distribution<int> numerator(-400, 400);
    long decided = 0, compared = 0;
    for (const Rational& p : {Rational(1, 10), Rational(3, 10), Rational(9, 20)}) {
        const Superball body = make_superball(3, p);
        for (int trial = 0; trial < 300; ++trial) {
            superpack_checker::RationalVector exact;
            std::vector<DInterval> v;
            for (int j = 0; j < 3; ++j) {
                exact[j] = mpq_class(numerator(random), 200);
                v.push_back(Binary64{}.rational(exact[j]));
            }
            const Outcome ours = star_disjoint_by_cases(body, v);
            const auto theirs = superpack_checker::star_cases(exact, 2 * p, 128);
            INFO("v = (" << exact[0] << ", " << exact[1] << ", " << exact[2] << "), p = " << p);
            if (ours == Outcome::proved) CHECK(theirs == superpack_checker::StarVerdict::disjoint);
            if (ours == Outcome::refuted) CHECK(theirs == superpack_checker::StarVerdict::overlapping);
            decided += ours != Outcome::undecided;
            StarOverlapOptions boxes_only;
            boxes_only.closed_form = false;
            boxes_only.max_boxes = 20000;
            const Outcome cover = star_overlap(body, v, boxes_only).disjoint;
            if (cover != Outcome::undecided && ours != Outcome::undecided) {
                CHECK(cover == ours);
                ++compared;
            }
        }
    }
    CHECK(decided == 900);  // random rationals are never at a threshold
    CHECK(compared > 800);
}

TEST_CASE("check-lattice and best below 1/2 write certificates that verify on the command line") {
    const std::string folder = std::filesystem::temp_directory_path() / "superpack-test-star-certificate";
    std::filesystem::create_directories(folder);
    const std::string good = folder + "/good.json", bad = folder + "/bad.json", insertion = folder + "/insertion.json",
                      best = folder + "/best.json";
    REQUIRE(run(std::string("check-lattice --p 0.3 --basis '") + minkowski + "' --certificate " + good).status == 0);
    CHECK(run("verify " + good).status == 0);
    std::ifstream in(good);
    Document document = Document::parse(in);
    document["proof"]["candidates"].erase(0);
    std::ofstream(bad) << document.dump(1);
    CHECK(run("verify " + bad).status == 1);
    REQUIRE(run("check-lattice --p 0.3 --family minkowski-insertion --certificate " + insertion).status == 0);
    CHECK(run("verify " + insertion).status == 0);
    REQUIRE(run("best --p 0.45 --certificate " + best).status == 0);
    const Run verified = run("verify " + best + " --json");
    CHECK(verified.status == 0);
    CHECK(verified.out.find("star-lattice-check") != std::string::npos);
    std::filesystem::remove_all(folder);
}

TEST_CASE("at an arm-to-arm contact the case tests decide only what their precision resolves, never the wrong side") {
    // v = (a, 1/2, 0) at p = 3/10: the interiors meet iff a < a* = 1 + (1 - 2^-q)^(1/q)
    // (scripts/make_star_threshold.py, mpmath at 160 digits). Rationals 10^-120 on either side.
    std::ifstream file(std::string(SUPERPACK_TEST_DATA) + "/star_threshold.json");
    const auto data = nlohmann::json::parse(file);
    const std::string digits = data["threshold"];
    const std::string fraction = digits.substr(2, 120);
    const mpq_class scale("1" + std::string(120, '0'));
    const mpq_class below = 1 + mpq_class(fraction) / scale, above = below + 1 / scale;
    const mpq_class q = mpq_class(3, 5), half(1, 2);
    using superpack_checker::StarVerdict;
    const auto checker = [&](const mpq_class& a, mpfr_prec_t precision) {
        return superpack_checker::star_cases({a, half, 0}, q, precision);
    };
    // 128 bits cannot see 10^-120: neither side may be claimed.
    CHECK(checker(below, 128) == StarVerdict::undecided);
    CHECK(checker(above, 128) == StarVerdict::undecided);
    CHECK(checker(below, 512) == StarVerdict::overlapping);
    CHECK(checker(above, 512) == StarVerdict::disjoint);
    const Superball body = make_superball(3, Rational(3, 10));
    for (const mpq_class& a : {below, above}) {
        const std::vector<DInterval> v{Binary64{}.rational(Rational(a)), Binary64{}.rational(Rational(half)), Binary64{}.rational(0)};
        CHECK(star_disjoint_by_cases(body, v) == Outcome::undecided);
        const BallField precise{640};  // 10^-120 is 2^-399
        const std::vector<Ball> sharp{precise.rational(Rational(a)), precise.rational(Rational(half)), precise.rational(0)};
        CHECK(star_disjoint_by_cases(body, sharp) == (a == below ? Outcome::refuted : Outcome::proved));
    }
}
