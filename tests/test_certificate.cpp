// Certificates and the independent checker: tampering with a bound, a case or p is rejected
// with the failing step named; malformed files are told apart; the checker includes
// nothing of the producer's arithmetic.
#include <filesystem>
#include <functional>
#include <iostream>

#include "checker/verifier.hpp"
#include "superpack/cert/certificate.hpp"
#include "superpack/arith/exact_ends.hpp"
#include "superpack/cert/family_certificate.hpp"
#include "superpack/cert/lattice_certificate.hpp"
#include "support.hpp"
#include "tamper.hpp"

namespace {

using superpack_checker::Verdict;
using superpack_checker::verify_document;
using Document = nlohmann::json;
using superpack::test::collect_bounds;
using superpack::test::rejected_at;
using superpack::test::check_tampered_bound_rejected;
using superpack::test::tamper_inward;

Document certificate(superpack::Family family, const std::string& p) {
    const superpack::Rational exact = superpack::parse_rational(p);
    const auto lattice = superpack::enclose_family(family, exact, superpack::DoubleField{});
    return Document::parse(superpack::family_certificate(lattice, exact, superpack::DoubleField{}, 15).dump());
}

// The lattice-check certificate of an exact basis at an exact p (binary64 intervals).
Document lattice_certificate(const std::string& p, const std::string& basis) {
    const superpack::Rational exact = superpack::parse_rational(p);
    const superpack::Basis<superpack::Rational> rows = superpack::parse_basis(basis);
    const auto check = superpack::check_exact_lattice(rows, exact, superpack::DoubleField{});
    return Document::parse(superpack::lattice_certificate(check, rows, exact, superpack::DoubleField{}, 15).dump());
}

const char* const minkowski_basis = "2/3,2/3,-2/3; -1/3,4/3,-1/3; 1/3,-1/3,-4/3";
const char* const overlapping_basis = "3.9,2,0; -2,-2,0; 0,0,2";

}  // namespace

TEST_CASE("the certificate head describes itself and the checker accepts the untouched file") {
    const Document document = certificate(superpack::Family::C0, "1.5");
    CHECK(document["format"] == "superpack-certificate");
    CHECK(document["format_version"] == superpack::certificate_format_version);
    CHECK(document["rounding_self_test"]["passed"] == true);
    CHECK(document["claim"]["kind"] == "family-lattice");
    CHECK(document["inputs"]["p"] == "3/2");
    CHECK(verify_document(document).verdict == Verdict::valid);
}

TEST_CASE("the producer writes the checker's sentence, and nothing the checker rejects") {
    const Document document = certificate(superpack::Family::C0, "1.5");
    const auto report = verify_document(document);
    CHECK(report.rendered_claim == document["claim"]["text"]);
    // A document the checker rejects is never returned: the assembler replays it first.
    superpack::Json claim = superpack::Json::parse(document["claim"].dump());
    claim.erase("text");
    claim["data"]["phi"] = claim["data"]["volume"];  // phi = V_sb: not V_sb / |det B|
    const auto assemble = [&] {
        return superpack::certificate_document(superpack::certificate_head("density", superpack::DoubleField{}, 15), claim,
                                               superpack::Json::parse(document["inputs"].dump()),
                                               superpack::Json::parse(document["proof"].dump()));
    };
    CHECK_THROWS_AS(assemble(), superpack::CertificateRejected);
    try {
        assemble();
    } catch (const superpack::CertificateRejected& error) {
        CHECK(std::string(error.what()).find("rejects this certificate at claim.data.phi") != std::string::npos);
    }
}

TEST_CASE("endpoints are exact dyadic numbers") {
    mpfr_t x;
    mpfr_init2(x, 53);
    mpfr_set_d(x, 0.375, MPFR_RNDN);
    CHECK(superpack::dyadic_text(x) == "3*2^-3");
    mpfr_set_d(x, -6.0, MPFR_RNDN);
    CHECK(superpack::dyadic_text(x) == "-3*2^1");
    mpfr_set_d(x, 5.0, MPFR_RNDN);
    CHECK(superpack::dyadic_text(x) == "5");
    mpfr_set_zero(x, 1);
    CHECK(superpack::dyadic_text(x) == "0");
    mpfr_clear(x);
}

TEST_CASE("changing a digit of any bound is rejected, naming a step") {
    long tampered = 0;
    for (const auto& [family, p] : {std::pair{superpack::Family::C0, "1.5"}, {superpack::Family::O0, "0.85"},
                                    {superpack::Family::O1, "0.6"}}) {
        const Document original = certificate(family, p);
        std::vector<std::string> bounds;
        collect_bounds(original["claim"], "/claim", bounds);
        collect_bounds(original["proof"], "/proof", bounds);
        REQUIRE(!bounds.empty());
        for (const std::string& bound : bounds) {
            check_tampered_bound_rejected(original, bound);
            ++tampered;
        }
    }
    std::cout << "tamper: " << tampered << " single-digit changes of bounds, every one rejected\n";
}

TEST_CASE("deleting a case is rejected at that case") {
    const Document original = certificate(superpack::Family::O1, "0.6");
    // Drop the second case of the first split: the split no longer covers its box.
    Document without_case = original;
    Document& split = without_case["proof"]["parameters"]["cases"][0];
    split["cases"].erase(1);
    CHECK(rejected_at(without_case) == "proof.parameters.cases[0].cases");
    // Replace a split by one of its halves: the parent's cover check fails.
    Document half = original;
    const Document& halves = original["proof"]["parameters"]["cases"][0]["cases"][1]["cases"];
    half["proof"]["parameters"]["cases"][0]["cases"][1] = Document(halves[0]);
    auto report = verify_document(half);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.parameters.cases[0].cases[1]", 0) == 0);
    // C0: drop the root-free partition.
    Document cubic = certificate(superpack::Family::C0, "1.5");
    cubic["proof"]["parameters"]["cases"].erase(1);
    CHECK(rejected_at(cubic) == "proof.parameters.cases");
}

TEST_CASE("changing p is rejected") {
    Document both = certificate(superpack::Family::C0, "1.5");
    both["inputs"]["p"] = "31/20";
    both["claim"]["data"]["p"] = "31/20";
    auto report = verify_document(both);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.parameters.cases[0]", 0) == 0);  // the Newton step fails first
    Document input_only = certificate(superpack::Family::O0, "0.85");
    input_only["inputs"]["p"] = "43/50";
    CHECK(rejected_at(input_only) == "inputs.p");
    Document outside = certificate(superpack::Family::O1, "0.6");
    outside["inputs"]["p"] = outside["claim"]["data"]["p"] = "4/5";  // beyond p*_o = ln3/ln4
    CHECK(verify_document(outside).verdict == Verdict::invalid);
}

TEST_CASE("a failed producer self-test, a foreign format and bad numbers are told apart") {
    Document failed = certificate(superpack::Family::O0, "0.85");
    failed["rounding_self_test"]["passed"] = false;
    CHECK(rejected_at(failed) == "rounding_self_test.passed");
    Document foreign = failed;
    foreign["format_version"] = 1;  // the format before the checker rendered the claim
    CHECK(verify_document(foreign).verdict == Verdict::malformed);
    Document decimal = certificate(superpack::Family::O0, "0.85");
    decimal["claim"]["data"]["phi"]["lo"] = "0.7656";  // a rounded decimal is not an exact endpoint
    auto report = verify_document(decimal);
    CHECK(report.verdict == Verdict::malformed);
    CHECK(report.path == "claim.data.phi");
    Document unknown = certificate(superpack::Family::O0, "0.85");
    unknown["claim"]["kind"] = "no-such-claim";
    CHECK(verify_document(unknown).verdict == Verdict::malformed);
}

TEST_CASE("verify on the command line: exit 0, 1 naming the step, 2 unreadable") {
    const std::string folder = std::filesystem::temp_directory_path() / "superpack-test-certificate";
    std::filesystem::create_directories(folder);
    const std::string good = folder + "/good.json", bad = folder + "/bad.json", junk = folder + "/junk.json",
                      err = folder + "/err.txt";
    auto status = [&](const std::string& arguments) {
        const int raw = std::system((std::string(SUPERPACK_BINARY) + " " + arguments + " >/dev/null 2>" + err).c_str());
        return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    };
    REQUIRE(status("density --family C1 --p 3 --certificate " + good) == 0);
    CHECK(status("verify " + good) == 0);
    std::ifstream in(good);
    Document document = Document::parse(in);
    document["claim"]["data"]["phi"]["hi"] = tamper_inward(document["claim"]["data"]["phi"]["hi"], false);
    std::ofstream(bad) << document.dump(1);
    CHECK(status("verify " + bad) == 1);
    std::ifstream message(err);
    const std::string line((std::istreambuf_iterator<char>(message)), {});
    CHECK(line.find("claim.data.phi") != std::string::npos);
    std::ofstream(junk) << "{ not json";
    CHECK(status("verify " + junk) == 2);
    CHECK(status("verify " + folder + "/missing.json") == 2);
    // Only proofs are certified: no certificate for a certified impossibility.
    const std::string none = folder + "/none.json";
    CHECK(status("density --family O1 --p 1 --certificate " + none) == 3);
    CHECK(!std::filesystem::exists(none));
    CHECK(status("density --family C0 --p 2 --certificate /proc/no/such/dir/c.json") == 2);
    std::filesystem::remove_all(folder);
}

TEST_CASE("lattice-check certificates: the three of proofs/ are valid and say what they claim") {
    const Document minkowski = lattice_certificate("1/2", minkowski_basis);
    CHECK(minkowski["claim"]["kind"] == "lattice-check");
    CHECK(minkowski["claim"]["data"]["packing"] == true);
    CHECK(minkowski["claim"]["data"]["contacts"] == 14);
    CHECK(verify_document(minkowski).verdict == Verdict::valid);
    const Document cubic = lattice_certificate("3", "2,0,0; 0,2,0; 0,0,2");
    CHECK(cubic["claim"]["data"]["contacts"] == 6);
    CHECK(verify_document(cubic).verdict == Verdict::valid);
    // 2p = 3/2 is not an integer: the contacts (2,0,0) are decided by the equal-coordinates test.
    CHECK(verify_document(lattice_certificate("3/4", "2,0,0; 0,2,0; 0,0,2")).verdict == Verdict::valid);
    const Document overlapping = lattice_certificate("2", overlapping_basis);
    CHECK(overlapping["claim"]["data"]["packing"] == false);
    CHECK(overlapping["claim"]["data"]["witness"]["coefficients"] == Document::array({1, 1, 0}));
    CHECK(verify_document(overlapping).verdict == Verdict::valid);
}

TEST_CASE("lattice-check: changing a digit of any bound is rejected, naming a step") {
    long tampered = 0;
    for (const auto& [p, basis] : {std::pair{"1/2", minkowski_basis}, {"2", overlapping_basis}}) {
        const Document original = lattice_certificate(p, basis);
        std::vector<std::string> bounds;
        collect_bounds(original["claim"], "/claim", bounds);
        collect_bounds(original["proof"], "/proof", bounds);
        REQUIRE(bounds.size() > 10);
        for (const std::string& bound : bounds) {
            check_tampered_bound_rejected(original, bound);
            ++tampered;
        }
    }
    std::cout << "tamper (lattice-check): " << tampered << " single-digit changes of bounds, every one rejected\n";
}

TEST_CASE("lattice-check: a lowered coefficient bound, a deleted candidate, a changed p or basis entry is rejected") {
    const Document original = lattice_certificate("1/2", minkowski_basis);
    REQUIRE(original["proof"]["coefficient_bound"] == Document::array({3, 3, 3}));
    Document bound = original;
    bound["proof"]["coefficient_bound"][1] = 2;
    CHECK(rejected_at(bound) == "proof.coefficient_bound");

    for (std::size_t k : {std::size_t{0}, original["proof"]["candidates"].size() / 2}) {
        Document deleted = original;
        deleted["proof"]["candidates"].erase(k);
        auto report = verify_document(deleted);
        INFO("candidate " << k);
        CHECK(report.verdict == Verdict::invalid);
        CHECK(report.path == "proof.candidates");
    }
    // A contact relabelled: the checker decides each status itself.
    Document relabelled = original;
    for (auto& candidate : relabelled["proof"]["candidates"])
        if (candidate["status"] == "contact") {
            candidate["status"] = "above";
            break;
        }
    CHECK(verify_document(relabelled).verdict == Verdict::invalid);

    Document p_both = original;
    p_both["inputs"]["p"] = p_both["claim"]["data"]["p"] = "3/5";
    auto report = verify_document(p_both);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.candidates[", 0) == 0);
    Document p_input = original;
    p_input["inputs"]["p"] = "3/5";
    CHECK(rejected_at(p_input) == "inputs.p");
    Document p_convex = original;
    p_convex["inputs"]["p"] = p_convex["claim"]["data"]["p"] = "2/5";
    CHECK(rejected_at(p_convex) == "inputs.p");

    Document entry_both = original;
    entry_both["inputs"]["basis"][0][0] = entry_both["claim"]["data"]["basis"][0][0] = "3/4";
    report = verify_document(entry_both);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.", 0) == 0);
    Document entry_input = original;
    entry_input["inputs"]["basis"][2][1] = "-1/2";
    CHECK(rejected_at(entry_input) == "inputs.basis");

    // Overlap: the witness must be certainly below 2; a packing claim over it is refuted.
    const Document overlapping = lattice_certificate("2", overlapping_basis);
    Document claimed_packing = overlapping;
    claimed_packing["claim"]["data"]["packing"] = true;
    report = verify_document(claimed_packing);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.candidates[", 0) == 0);
    // A near contact in binary64 beside a witness: the producer marks it undecided, the checker
    // (128 bits) separates it from 2 and accepts the overlap.
    const Document near = lattice_certificate("2", "3.9,2,0; -2,-2,0; 0,0,2.0000000000000001");
    bool undecided = false;
    for (const auto& candidate : near["proof"]["candidates"]) undecided = undecided || candidate["status"] == "undecided";
    CHECK(undecided);
    CHECK(verify_document(near).verdict == Verdict::valid);
    Document other_witness = overlapping;
    other_witness["claim"]["data"]["witness"]["coefficients"] = Document::array({0, 0, 1});
    CHECK(verify_document(other_witness).verdict == Verdict::invalid);
}

TEST_CASE("check-lattice --certificate on the command line") {
    const std::string folder = std::filesystem::temp_directory_path() / "superpack-test-lattice-certificate";
    std::filesystem::create_directories(folder);
    const std::string good = folder + "/good.json", bad = folder + "/bad.json", none = folder + "/none.json";
    auto status = [&](const std::string& arguments) {
        const int raw = std::system((std::string(SUPERPACK_BINARY) + " " + arguments + " >/dev/null 2>&1").c_str());
        return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    };
    REQUIRE(status("check-lattice --p 3 --basis '2,0,0; 0,2,0; 0,0,2' --certificate " + good) == 0);
    CHECK(status("verify " + good) == 0);
    std::ifstream in(good);
    Document document = Document::parse(in);
    document["claim"]["data"]["contacts"] = 8;
    std::ofstream(bad) << document.dump(1);
    CHECK(status("verify " + bad) == 1);
    // A near contact in binary64 is undecided: exit 4 and no certificate.
    CHECK(status("check-lattice --p 1 --basis '2,0,0; 0,2,0; 0,0,2.0000000000000001' --certificate " + none) == 4);
    CHECK(!std::filesystem::exists(none));
    // Outside the family's domain: bad input, no certificate (family certificates: test_certificate_audit.cpp).
    CHECK(status("check-lattice --p 0.9 --family C0 --certificate " + none) == 2);
    CHECK(!std::filesystem::exists(none));
    std::filesystem::remove_all(folder);
}

TEST_CASE("density certificates of C0 and C1 at p = 10^4 and 10^6 verify, in both backends") {
    for (const char* p_text : {"10000", "1000000"})
        for (superpack::Family family : {superpack::Family::C0, superpack::Family::C1}) {
            INFO(superpack::to_string(family) << " at p = " << p_text);
            CHECK(verify_document(certificate(family, p_text)).verdict == Verdict::valid);
            const superpack::Rational p = superpack::parse_rational(p_text);
            const superpack::BallField thirty{superpack::bits_for_digits(30)};
            const auto lattice = superpack::enclose_family(family, p, thirty);
            REQUIRE(lattice.status == superpack::Outcome::proved);
            CHECK(verify_document(Document::parse(superpack::family_certificate(lattice, p, thirty, 30).dump())).verdict ==
                  Verdict::valid);
        }
}
