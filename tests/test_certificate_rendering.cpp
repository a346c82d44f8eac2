// The words of a certificate are the checker's (NOTES.md 8.2): it renders the claim sentence and
// every "decimal" from what it verified and reads every key, so a forged claim text, a forged
// decimal, an unknown or repeated key and a forged literature value are each rejected at the
// named path,
// and "packing density" appears only where the same certificate proves a packing.
#include <filesystem>
#include <fstream>

#include "checker/core/json_reader.hpp"
#include "checker/verifier.hpp"
#include "superpack/cert/audit_certificate.hpp"
#include "superpack/cert/crossover_certificate.hpp"
#include "superpack/cert/family_certificate.hpp"
#include "superpack/cert/lattice_certificate.hpp"
#include "support.hpp"
#include "tamper.hpp"

namespace {

using superpack::Family;
using superpack::test::rejected_at;
using Document = nlohmann::json;

const superpack::DoubleField binary64{};

Document density(Family family, const std::string& p) {
    const superpack::Rational exact = superpack::parse_rational(p);
    return Document::parse(superpack::family_certificate(superpack::enclose_family(family, exact, binary64), exact, binary64, 15).dump());
}

Document family_check(Family family, const std::string& p) {
    const superpack::Rational exact = superpack::parse_rational(p);
    const auto lattice = superpack::enclose_family(family, exact, binary64);
    const auto check = superpack::check_family_lattice(lattice, binary64.rational(exact));
    return Document::parse(superpack::family_lattice_check_certificate(lattice, check, exact, binary64, 15).dump());
}

Document overlapping_lattice() {
    const superpack::Rational p = superpack::parse_rational("2");
    const auto basis = superpack::parse_basis("3.9,2,0; -2,-2,0; 0,0,2");
    return Document::parse(
        superpack::lattice_certificate(superpack::check_exact_lattice(basis, p, binary64), basis, p, binary64, 15).dump());
}

const Document& slopes() {
    static const Document document =
        Document::parse(superpack::sphere_slopes_certificate(superpack::certify_sphere_slopes(binary64), binary64, 15).dump());
    return document;
}

std::string text_of(const Document& document) { return document["claim"]["text"].get<std::string>(); }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The text with its negated uses removed ("is not a packing density", "not claimed to be a
// packing density"): what remains says "packing density" only as a claim.
std::string claimed_words(std::string text) {
    for (const std::string negated : {"is not a packing density", "not claimed to be a packing density"})
        for (std::size_t at = text.find(negated); at != std::string::npos; at = text.find(negated)) text.erase(at, negated.size());
    return text;
}

// The file's text with `insertion` put right after the first occurrence of `after`, checked by
// verify_file as superpack verify reads it.
superpack_checker::VerifyReport verify_text_with(const Document& document, const std::string& after, const std::string& insertion) {
    std::string text = document.dump();
    const std::size_t at = text.find(after);
    REQUIRE(at != std::string::npos);
    text.insert(at + after.size(), insertion);
    return superpack_checker::verify_text(text);
}

}  // namespace

TEST_CASE("a forged claim text is rejected at claim.text") {
    Document forged = slopes();
    forged["claim"]["text"] = "The paper is right: a_plus = 0.3555";
    CHECK(rejected_at(forged) == "claim.text");
    // The old sentence of density-O1-p0.6.json, for a lattice that overlaps.
    Document o1 = density(Family::O1, "0.6");
    o1["claim"]["text"] = "The O1 lattice of Jiao, Stillinger and Torquato (2009) at p = 3/5 has packing density 0.8804";
    CHECK(rejected_at(o1) == "claim.text");
    // One character: the verdict of a lattice check turned around.
    Document check = family_check(Family::O1, "0.6");
    std::string text = text_of(check);
    const std::size_t at = text.find("is not a packing");
    REQUIRE(at != std::string::npos);
    check["claim"]["text"] = text.replace(at, 16, "is a packing    ");
    CHECK(rejected_at(check) == "claim.text");
}

TEST_CASE("a forged decimal is rejected at its path") {
    Document phi = density(Family::C0, "1.5");
    phi["claim"]["data"]["phi"]["decimal"] = "[0.8, 0.81]";
    CHECK(rejected_at(phi) == "claim.data.phi.decimal");
    Document slope = slopes();
    slope["claim"]["data"]["a_plus"]["value"]["decimal"] = "[3.5550000000000000e-01, 3.5560000000000000e-01]";
    CHECK(rejected_at(slope) == "claim.data.a_plus.value.decimal");
    // Deep in a proof, and a decimal that is the right one rounded the wrong way (hi down).
    Document norm = overlapping_lattice();
    Document& decimal = norm["proof"]["candidates"][0]["norm"]["decimal"];
    std::string text = decimal.get<std::string>();
    // The last nonzero digit of hi lowered by one (hi may be exact, with trailing zeros).
    const std::size_t last = text.find_last_of("123456789", text.rfind('e'));
    REQUIRE(last != std::string::npos);
    --text[last];
    decimal = text;
    CHECK(rejected_at(norm) == "proof.candidates[0].norm.decimal");
}

TEST_CASE("an unknown key is rejected at its path") {
    Document data = density(Family::O0, "0.85");
    data["claim"]["data"]["note"] = "this lattice is the densest packing";
    CHECK(rejected_at(data) == "claim.data.note");
    Document input = density(Family::O0, "0.85");
    input["inputs"]["trusted"] = true;
    CHECK(rejected_at(input) == "inputs.trusted");
    Document proof = overlapping_lattice();
    proof["proof"]["candidates"][1]["reason"] = "checked by hand";
    CHECK(rejected_at(proof) == "proof.candidates[1].reason");
    Document top = slopes();
    top["errata"] = "none";
    CHECK(rejected_at(top) == "errata");
}

TEST_CASE("a repeated key is rejected at its path") {
    // Two claim texts: nlohmann keeps the last, so a reader of the first would see another claim.
    const auto text = verify_text_with(slopes(), "\"claim\":{", "\"text\":\"The paper is right: a_plus = 0.3555\",");
    CHECK(text.verdict == superpack_checker::Verdict::malformed);
    CHECK(text.path == "claim.text");
    CHECK(text.message.find("duplicate key") != std::string::npos);
    // Deep in a proof, inside an array.
    const Document lattice = overlapping_lattice();
    const std::string first = "\"candidates\":[{";
    const auto nested = verify_text_with(lattice, first, "\"norm\":" + lattice["proof"]["candidates"][0]["norm"].dump() + ",");
    CHECK(nested.path == "proof.candidates[0].norm");
    // The same key in two objects, and in an array's later element, is no repetition.
    const superpack_checker::JsonReading parsed =
        superpack_checker::read_json(std::string(R"({"a": {"k": 1}, "b": [{"k": 2}, {"k": 3, "j": [1, {"k": 4}]}]})"));
    REQUIRE(parsed.ok);
    CHECK(parsed.document["b"][1]["j"][1]["k"] == 4);
    const superpack_checker::JsonReading repeated =
        superpack_checker::read_json(std::string(R"({"a": [1, 2, {"x": [0, {"k": 1, "k": 2}]}]})"));
    CHECK(!repeated.ok);
    CHECK(repeated.path == "a[2].x[1].k");
    // Unchanged, the file verifies through the same reader.
    CHECK(verify_text_with(slopes(), "", "").verdict == superpack_checker::Verdict::valid);
}

TEST_CASE("a forged literature value is rejected at its path") {
    // The paper's printed a_plus replaced, with every verdict about it "undecided" (which claims
    // nothing): only the checker's own table can tell the digits are not the paper's.
    Document forged = slopes();
    Document& paper = forged["claim"]["data"]["paper"]["a_plus"];
    paper["printed"] = "0.1236";
    for (const char* reading : {"as_truncated", "as_rounded"}) {
        paper["certified_vs_printed"][reading] = "undecided";
        paper["closed_form_vs_printed"][reading] = "undecided";
    }
    CHECK(rejected_at(forged) == "claim.data.paper.a_plus.printed");
    Document minus = slopes();
    minus["claim"]["data"]["paper"]["a_minus"]["printed"] = "-0.0294";
    for (const char* reading : {"as_truncated", "as_rounded"})
        minus["claim"]["data"]["paper"]["a_minus"]["certified_vs_printed"][reading] = "undecided";
    CHECK(rejected_at(minus) == "claim.data.paper.a_minus.printed");
}

TEST_CASE("the slope sentence states the erratum from the checker's table") {
    const std::string text = text_of(slopes());
    CHECK(contains(text, "a_plus (Eq. (6), Sec. III.A)"));
    CHECK(contains(text, "0.3555..."));
    CHECK(contains(text, "is neither the certified a_plus truncated nor rounded to 4 decimals"));
    CHECK(contains(text, "wrong twice"));
    CHECK(contains(text, "0.12366686063810"));
}

TEST_CASE("packing density only where the certificate proves a packing") {
    const Document o1 = density(Family::O1, "0.6");
    CHECK(o1["claim"]["data"]["verdict"] == "overlapping");
    CHECK(contains(text_of(o1), "is not a packing"));
    CHECK(!contains(claimed_words(text_of(o1)), "packing density"));
    CHECK(contains(text_of(o1), "Sec. IV.B"));  // the paper's claim it refutes
    const Document c0 = density(Family::C0, "1.5");
    CHECK(c0["claim"]["data"]["verdict"] == "packing");
    CHECK(contains(text_of(c0), "of packing density phi = V_sb(p) / |det B|"));
    // Minkowski's lattice: e1 - e2 - e3 has norm exactly 2 but follows from no equation of O1,
    // so the family check is undecided and the ratio is not called a packing density.
    const Document minkowski = density(Family::O1, "1/2");
    CHECK(minkowski["claim"]["data"]["verdict"] == "undecided");
    CHECK(!contains(claimed_words(text_of(minkowski)), "packing density"));
    CHECK(!contains(text_of(minkowski), "not a packing:"));
    // O0 near p = 1/2: V_sb / |det B| = 119 > 1 rules a packing out without the enumeration.
    const Document dense = density(Family::O0, "0.501");
    CHECK(dense["claim"]["data"]["verdict"] == "undecided");
    CHECK(contains(text_of(dense), "above 1, so it is not a packing"));
    CHECK(!contains(claimed_words(text_of(dense)), "packing density"));

    // proofs/: "packing density" in a sentence only where that certificate proves a packing.
    const std::filesystem::path folder = std::filesystem::path(SUPERPACK_TEST_DATA) / ".." / ".." / "proofs";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") continue;
        std::ifstream file(entry.path());
        const Document document = Document::parse(file);
        const Document& data = document["claim"]["data"];
        const std::string kind = document["claim"]["kind"];
        const bool packing = (kind == "family-lattice" && data.value("verdict", "") == "packing") ||
                             ((kind == "lattice-check" || kind == "star-lattice-check" || kind == "periodic-packing") &&
                              data["packing"] == true) ||
                             kind == "superdisk-optimum" ||
                             kind == "local-optimum";
        INFO(entry.path().filename() << ": " << text_of(document));
        CHECK(contains(claimed_words(text_of(document)), "packing density") == packing);
        ++files;
    }
    CHECK(files >= 41);
}
