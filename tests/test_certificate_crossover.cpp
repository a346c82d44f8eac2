// Certificates of the crossovers and slopes (claim kinds cubic-crossover, octahedral-crossover,
// sphere-slopes; NOTES.md 8.5): the files in proofs/ are valid and hold the mpmath values;
// tampering with a bound, a piece, a case, a lemma value or an input is rejected with the
// failing step named; the CLI writes atomically and writes nothing without a proof.
#include <filesystem>
#include <iostream>

#include "checker/verifier.hpp"
#include "crossover_reference.hpp"
#include "superpack/cert/crossover_certificate.hpp"
#include "support.hpp"
#include "tamper.hpp"

namespace {

using superpack::test::collect_bounds;
using superpack::test::proof_step;
using superpack::test::reference_text;
using superpack::test::rejected_at;
using superpack::test::tamper_bound;
using superpack_checker::Verdict;
using superpack_checker::verify_document;
using Document = nlohmann::json;

const superpack::DoubleField binary64{};

const Document& cubic_certificate() {
    static const Document document = Document::parse(
        superpack::cubic_crossover_certificate(superpack::certify_cubic_crossover(binary64, 15), binary64, 15).dump());
    return document;
}
const Document& octahedral_certificate() {
    static const Document document = Document::parse(
        superpack::octahedral_crossover_certificate(superpack::certify_octahedral_crossover(binary64, 15), binary64, 15).dump());
    return document;
}
const Document& slopes_certificate() {
    static const Document document =
        Document::parse(superpack::sphere_slopes_certificate(superpack::certify_sphere_slopes(binary64), binary64, 15).dump());
    return document;
}

// "m*2^e" exactly as a rational.
mpq_class dyadic(const std::string& text) {
    const std::size_t star = text.find('*');
    mpq_class value(mpz_class(text.substr(0, star), 10));
    if (star != std::string::npos) {
        const long exponent = std::stol(text.substr(star + 3));
        mpz_class power = 1;
        power <<= static_cast<unsigned long>(std::labs(exponent));
        value = exponent >= 0 ? mpq_class(value * power) : mpq_class(value / power);
    }
    value.canonicalize();
    return value;
}

// The exact interval holds the reference decimal (given to 50 digits: a 1e-48 margin).
bool holds(const Document& interval, const std::string& decimal) {
    mpq_class value = superpack::parse_rational(decimal);
    const mpq_class margin(1, mpz_class("1000000000000000000000000000000000000000000000000"));
    return dyadic(interval["lo"]) <= value + margin && value - margin <= dyadic(interval["hi"]);
}

superpack_checker::VerifyReport verify(const Document& document) { return verify_document(document); }

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

}  // namespace

TEST_CASE("crossover and slope certificates are valid and hold the mpmath values") {
    const Document& cubic = cubic_certificate();
    CHECK(cubic["claim"]["kind"] == "cubic-crossover");
    CHECK(cubic["command"] == "crossover cubic");
    CHECK(verify(cubic).verdict == Verdict::valid);
    CHECK(holds(cubic["claim"]["data"]["p"], reference_text("p_c")));
    CHECK(holds(cubic["claim"]["data"]["phi"], reference_text("phi_c")));
    CHECK(cubic["claim"]["data"]["densest_left"] == "C0");
    std::size_t roots = 0;
    for (const auto& piece : cubic["proof"]["pieces"]) roots += piece["claim"] == "root";
    CHECK(roots == 1);

    const Document& octahedral = octahedral_certificate();
    CHECK(octahedral["claim"]["kind"] == "octahedral-crossover");
    CHECK(verify(octahedral).verdict == Verdict::valid);
    CHECK(holds(octahedral["claim"]["data"]["p"], reference_text("p_o")));
    CHECK(holds(octahedral["claim"]["data"]["phi"], reference_text("phi_o")));

    const Document& slopes = slopes_certificate();
    CHECK(slopes["claim"]["kind"] == "sphere-slopes");
    CHECK(verify(slopes).verdict == Verdict::valid);
    const auto& reference_slopes = superpack::test::crossover_reference()["slopes"];
    for (const char* family : {"C0", "C1", "O0"})
        CHECK(holds(slopes["claim"]["data"][family]["slope"], reference_slopes[family]["1"].get<std::string>()));
    CHECK(holds(slopes["claim"]["data"]["a_plus"]["value"], reference_slopes["C0"]["1"].get<std::string>()));
    CHECK(holds(slopes["claim"]["data"]["paper"]["a_plus"]["closed_form"], reference_text("closed_a_plus")));
    CHECK(holds(slopes["claim"]["data"]["paper"]["a_minus"]["closed_form"], reference_text("closed_a_minus")));
    // The erratum is stated plainly: a_plus disagrees with both the closed form and 0.3555.
    CHECK(slopes["claim"]["data"]["paper"]["a_plus"]["certified_vs_closed_form"] == "disagree");
    CHECK(slopes["claim"]["data"]["paper"]["a_plus"]["certified_vs_printed"]["as_truncated"] == "disagree");
    CHECK(slopes["claim"]["text"].get<std::string>().find("0.123666860638") != std::string::npos);
}

TEST_CASE("crossover certificates: changing a digit of a bound is rejected, naming a step") {
    // Every bound of the octahedral and slope certificates; of the cubic one, the claim and the
    // first two pieces (p = 1), the three around the root, the middle one and the last (each
    // replay walks the pieces up to the tampered one, 0.1-0.3 s).
    std::vector<std::pair<const Document*, std::string>> cases;
    for (const Document* document : {&octahedral_certificate(), &slopes_certificate()}) {
        std::vector<std::string> bounds;
        collect_bounds((*document)["claim"], "/claim", bounds);
        collect_bounds((*document)["proof"], "/proof", bounds);
        for (const std::string& bound : bounds) cases.push_back({document, bound});
    }
    const Document& cubic = cubic_certificate();
    const auto& pieces = cubic["proof"]["pieces"];
    std::size_t root = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k)
        if (pieces[k]["claim"] == "root") root = k;
    std::vector<std::string> bounds;
    collect_bounds(cubic["claim"], "/claim", bounds);
    for (std::size_t k = 0; k < pieces.size(); ++k)
        if (k < 2 || (k + 1 >= root && k <= root + 1) || k == pieces.size() / 2 || k + 1 == pieces.size())
            collect_bounds(pieces[k], "/proof/pieces/" + std::to_string(k), bounds);
    for (const std::string& bound : bounds) cases.push_back({&cubic, bound});

    long rejected = 0;
    for (const auto& [original, bound] : cases) {
        Document copy = *original;
        const Document::json_pointer pointer(bound);
        const std::string before = copy[pointer].get<std::string>();
        tamper_bound(copy, bound);
        const auto report = verify(copy);
        INFO(bound << ": " << before << " -> " << copy[pointer] << " (" << report.path << ": " << report.message << ")");
        CHECK(report.verdict == Verdict::invalid);
        CHECK(proof_step(report.path));
        rejected += report.verdict == Verdict::invalid;
    }
    std::cout << "tamper (crossover, slopes): " << rejected << " of " << cases.size()
              << " single-digit changes of bounds rejected\n";
}

TEST_CASE("cubic crossover: a deleted piece, a changed sign, lemma value or input is rejected at its step") {
    const Document& original = cubic_certificate();
    const auto& pieces = original["proof"]["pieces"];
    std::size_t root = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k)
        if (pieces[k]["claim"] == "root") root = k;
    // A deleted piece leaves a gap where the next one starts.
    Document deleted = original;
    deleted["proof"]["pieces"].erase(1);
    CHECK(rejected_at(deleted) == "proof.pieces[1].p");
    Document without_root = original;
    without_root["proof"]["pieces"].erase(root);
    auto report = verify(without_root);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path == "proof.pieces[" + std::to_string(root) + "].p");
    Document without_last = original;
    without_last["proof"]["pieces"].erase(pieces.size() - 1);
    CHECK(rejected_at(without_last) == "proof.pieces");
    // The first piece (where g(1) = 0) claimed positive; a piece of the other sign; a second root.
    Document first = original;
    first["proof"]["pieces"][0]["claim"] = "positive";
    CHECK(rejected_at(first) == "proof.pieces[0]");
    Document flipped = original;
    flipped["proof"]["pieces"][root + 5]["claim"] = "negative";
    report = verify(flipped);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path == "proof.pieces[" + std::to_string(root + 5) + "]");
    Document second_root = original;
    second_root["proof"]["pieces"][root + 5]["claim"] = "root";
    second_root["proof"]["pieces"][root + 5]["root"] = original["claim"]["data"]["p"];
    report = verify(second_root);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(starts_with(report.path, "proof.pieces[" + std::to_string(root + 5) + "]"));
    // The claimed order of the densities.
    Document sides = original;
    sides["claim"]["data"]["sign_left"] = "positive";
    sides["claim"]["data"]["sign_right"] = "negative";
    CHECK(rejected_at(sides) == "claim.data.sign_right");
    Document densest = original;
    densest["claim"]["data"]["densest_left"] = "C1";
    CHECK(rejected_at(densest) == "claim.data.densest_left");
    // The exact values at p = 1: s_C0 = (2 - sqrt2)/4 is a + b sqrt2 with a = 1/2, b = -1/4.
    Document lemma = original;
    lemma["proof"]["at_start"]["s_C0"]["b"] = "-1/5";
    CHECK(rejected_at(lemma) == "proof.at_start.s_C0");
    // Inputs: another interval (both places, or the input only), a start away from p = 1.
    Document longer = original;
    longer["inputs"]["to"] = longer["claim"]["data"]["to"] = "11";
    CHECK(rejected_at(longer) == "proof.pieces");
    Document input_only = original;
    input_only["inputs"]["to"] = "9";
    CHECK(rejected_at(input_only) == "claim.data.to");
    Document start = original;
    start["inputs"]["from"] = start["claim"]["data"]["from"] = "11/10";
    CHECK(rejected_at(start) == "inputs.from");
}

TEST_CASE("octahedral crossover and slopes: a deleted case, a changed matrix, verdict or input is rejected") {
    const Document& octahedral = octahedral_certificate();
    Document deleted = octahedral;
    deleted["proof"]["cases"].erase(1);
    CHECK(rejected_at(deleted) == "proof.cases");
    Document unimodular = octahedral;
    unimodular["claim"]["data"]["lattice"]["unimodular"][2][2] = "1";
    CHECK(rejected_at(unimodular) == "claim.data.lattice.unimodular");
    Document basis = octahedral;
    basis["claim"]["data"]["lattice"]["O0"][2][2] = "9/10";  // 2c with c != 1/2
    CHECK(rejected_at(basis) == "claim.data.lattice.O0[2][2]");
    Document determinant = octahedral;
    determinant["claim"]["data"]["lattice"]["abs_determinant"] = "5";
    CHECK(rejected_at(determinant) == "claim.data.lattice.abs_determinant");
    Document domain = octahedral;
    domain["inputs"]["from"] = "0";
    CHECK(rejected_at(domain) == "inputs");
    // A Newton box beside the root: no root of Eq. (6) there.
    Document moved = octahedral;
    moved["proof"]["cases"][0]["box"]["hi"] = "3*2^-2";
    auto report = verify(moved);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(starts_with(report.path, "proof.cases[0]"));

    const Document& slopes = slopes_certificate();
    Document no_root = slopes;
    no_root["proof"]["cases"].erase(1);
    CHECK(rejected_at(no_root) == "proof.cases");
    Document swapped = slopes;
    swapped["proof"]["cases"][0]["family"] = "C1";
    CHECK(rejected_at(swapped) == "proof.cases[0].family");
    Document at_other_p = slopes;
    at_other_p["inputs"]["p"] = at_other_p["claim"]["data"]["p"] = "11/10";
    CHECK(rejected_at(at_other_p) == "inputs.p");
    // a_plus is the larger cubic slope: C0's, not C1's.
    Document family = slopes;
    family["claim"]["data"]["a_plus"]["family"] = "C1";
    CHECK(rejected_at(family) == "claim.data.a_plus.family");
    // The paper's printed a_plus made to agree: the checker decides each verdict itself.
    Document agreeing = slopes;
    agreeing["claim"]["data"]["paper"]["a_plus"]["certified_vs_printed"]["as_truncated"] = "agree";
    CHECK(rejected_at(agreeing) == "claim.data.paper.a_plus.certified_vs_printed.as_truncated");
    Document closed = slopes;
    closed["claim"]["data"]["paper"]["a_plus"]["certified_vs_closed_form"] = "agree";
    CHECK(rejected_at(closed) == "claim.data.paper.a_plus.certified_vs_closed_form");
    Document printed = slopes;
    printed["claim"]["data"]["paper"]["a_plus"]["printed"] = "0.1236";  // not the paper's (literature.hpp)
    CHECK(rejected_at(printed) == "claim.data.paper.a_plus.printed");
}

TEST_CASE("no certificate without a proof") {
    // The builders refuse an uncertified result, so the CLI has nothing to write.
    CHECK_THROWS_AS(superpack::cubic_crossover_certificate(superpack::CubicCrossover<superpack::DInterval>{}, binary64, 15),
                    std::runtime_error);
    CHECK_THROWS_AS(
        superpack::octahedral_crossover_certificate(superpack::OctahedralCrossover<superpack::DInterval>{}, binary64, 15),
        std::runtime_error);
    CHECK_THROWS_AS(superpack::sphere_slopes_certificate(superpack::SphereSlopes<superpack::DInterval>{}, binary64, 15),
                    std::runtime_error);
}

TEST_CASE("crossover and slopes --certificate on the command line") {
    const std::string folder = std::filesystem::temp_directory_path() / "superpack-test-crossover-certificate";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    auto status = [&](const std::string& arguments) {
        const int raw = std::system((std::string(SUPERPACK_BINARY) + " " + arguments + " >/dev/null 2>&1").c_str());
        return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    };
    // An old file at the path is replaced whole (temp file + rename): no trace of it, no temp left.
    const std::string octahedral = folder + "/octahedral.json", slopes = folder + "/slopes.json";
    std::ofstream(octahedral) << std::string(100000, 'x');
    REQUIRE(status("crossover octahedral --certificate " + octahedral) == 0);
    CHECK(status("verify " + octahedral) == 0);
    std::ifstream in(octahedral);
    const Document document = Document::parse(in);
    CHECK(document["claim"]["kind"] == "octahedral-crossover");
    REQUIRE(status("slopes --digits 20 --certificate " + slopes) == 0);
    CHECK(status("verify " + slopes) == 0);
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        INFO(entry.path());
        CHECK(entry.path().extension() == ".json");
        ++files;
    }
    CHECK(files == 2);
    // Bad usage computes nothing and writes nothing; an unwritable path is exit 2.
    const std::string none = folder + "/none.json";
    CHECK(status("crossover cubical --certificate " + none) == 2);
    CHECK(status("slopes --digits 0 --certificate " + none) == 2);
    CHECK(!std::filesystem::exists(none));
    CHECK(status("crossover octahedral --certificate /proc/no/such/dir/c.json") == 2);
    std::filesystem::remove_all(folder);
}
