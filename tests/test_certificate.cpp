// Certificates and the independent checker: tampering with a bound, a case or p is rejected
// with the failing step named; malformed files are told apart; the checker includes
// nothing of the producer's arithmetic.
#include <filesystem>
#include <functional>
#include <iostream>

#include "checker/verifier.hpp"
#include "superpack/certificate.hpp"
#include "superpack/family_certificate.hpp"
#include "support.hpp"

namespace {

using superpack_checker::Verdict;
using superpack_checker::verify_document;
using Document = nlohmann::json;

Document certificate(superpack::Family family, const std::string& p) {
    const superpack::Rational exact = superpack::parse_rational(p);
    const auto lattice = superpack::enclose_family(family, exact, superpack::DoubleField{});
    return Document::parse(superpack::family_certificate(lattice, exact, superpack::DoubleField{}, 15).dump());
}

// Every {"lo", "hi"} string in the claim's data and in the proof, as JSON pointers.
void collect_bounds(const Document& node, const std::string& pointer, std::vector<std::string>& bounds) {
    if (node.is_object()) {
        if (node.contains("lo") && node.contains("hi") && node["lo"].is_string()) {
            bounds.push_back(pointer + "/lo");
            bounds.push_back(pointer + "/hi");
            return;
        }
        for (const auto& [key, value] : node.items()) collect_bounds(value, pointer + "/" + key, bounds);
    } else if (node.is_array()) {
        for (std::size_t k = 0; k < node.size(); ++k) collect_bounds(node[k], pointer + "/" + std::to_string(k), bounds);
    }
}

// Changes the leading digit of the mantissa so that the bound moves inward (a lower end up,
// an upper end down): "5*2^-3" as a lower end becomes "6*2^-3", as an upper end "4*2^-3".
std::string tamper_inward(const std::string& text, bool lower) {
    if (text == "0") return lower ? "1" : "-1";
    const std::size_t star = text.find('*');
    std::string mantissa = text.substr(0, star);
    const std::string rest = star == std::string::npos ? "" : text.substr(star);
    const bool negative = mantissa[0] == '-';
    const std::size_t lead = negative ? 1 : 0;
    const bool grow = lower != negative;  // make |m| larger?
    if (grow) {
        if (mantissa[lead] == '9') mantissa.insert(lead, "1");
        else ++mantissa[lead];
    } else {
        --mantissa[lead];
        while (mantissa.size() > lead + 1 && mantissa[lead] == '0') mantissa.erase(lead, 1);
    }
    return mantissa + rest;
}

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
            Document copy = original;
            const Document::json_pointer pointer(bound);
            const std::string before = copy[pointer].get<std::string>();
            const std::string after = tamper_inward(before, bound.substr(bound.size() - 2) == "lo");
            copy[pointer] = after;
            const auto report = verify_document(copy);
            INFO(bound << ": " << before << " -> " << after);
            CHECK(report.verdict == Verdict::invalid);
            CHECK(!report.path.empty());
            ++tampered;
        }
    }
    std::cout << "tamper: " << tampered << " single-digit changes of bounds, every one rejected\n";
}

TEST_CASE("deleting a case is rejected at that case") {
    const Document original = certificate(superpack::Family::O1, "0.6");
    // Drop the second case of the first split: the split no longer covers its box.
    Document without_case = original;
    without_case["proof"]["cases"][0]["cases"].erase(1);
    auto report = verify_document(without_case);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path == "proof.cases[0].cases");
    // Replace a split by one of its halves: the parent's cover check fails.
    Document half = original;
    half["proof"]["cases"][0]["cases"][1] = Document(original["proof"]["cases"][0]["cases"][1]["cases"][0]);
    report = verify_document(half);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.cases[0].cases[1]", 0) == 0);
    // C0: drop the root-free partition.
    Document cubic = certificate(superpack::Family::C0, "1.5");
    cubic["proof"]["cases"].erase(1);
    report = verify_document(cubic);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path == "proof.cases");
}

TEST_CASE("changing p is rejected") {
    Document both = certificate(superpack::Family::C0, "1.5");
    both["inputs"]["p"] = "31/20";
    both["claim"]["data"]["p"] = "31/20";
    auto report = verify_document(both);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.cases[0]", 0) == 0);  // the Newton step fails first
    Document input_only = certificate(superpack::Family::O0, "0.85");
    input_only["inputs"]["p"] = "43/50";
    report = verify_document(input_only);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path == "inputs.p");
    Document outside = certificate(superpack::Family::O1, "0.6");
    outside["inputs"]["p"] = outside["claim"]["data"]["p"] = "4/5";  // beyond p*_o = ln3/ln4
    CHECK(verify_document(outside).verdict == Verdict::invalid);
}

TEST_CASE("a failed producer self-test, a foreign format and bad numbers are told apart") {
    Document failed = certificate(superpack::Family::O0, "0.85");
    failed["rounding_self_test"]["passed"] = false;
    auto report = verify_document(failed);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path == "rounding_self_test.passed");
    Document foreign = failed;
    foreign["format_version"] = 2;
    CHECK(verify_document(foreign).verdict == Verdict::malformed);
    Document decimal = certificate(superpack::Family::O0, "0.85");
    decimal["claim"]["data"]["phi"]["lo"] = "0.7656";  // a rounded decimal is not an exact endpoint
    report = verify_document(decimal);
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

TEST_CASE("the checker shares no evaluation code with the producer") {
    const std::filesystem::path folder = std::filesystem::path(SUPERPACK_TEST_DATA) / ".." / ".." / "checker";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        std::ifstream file(entry.path());
        const std::string text((std::istreambuf_iterator<char>(file)), {});
        INFO(entry.path());
        CHECK(text.find("superpack/") == std::string::npos);  // no include of include/superpack/*
        CHECK(text.find("arb.h") == std::string::npos);
        CHECK(text.find("boost") == std::string::npos);
        ++files;
    }
    CHECK(files >= 6);
}
