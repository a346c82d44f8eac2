// Certificates of the D14 family (Dostert and Vallentin 2020): density, family lattice check and
// audit verify, the checker's sentence names the source, and tampering with a bound, a case,
// the family, p, a contact count or the continuation chain is rejected naming the step.
#include "checker/verifier.hpp"
#include "superpack/cert/audit_certificate.hpp"
#include "superpack/cert/family_certificate.hpp"
#include "support.hpp"
#include "tamper.hpp"

namespace {

using superpack::Family;
using superpack::Rational;
using superpack_checker::Verdict;
using superpack_checker::verify_document;
using superpack::test::collect_bounds;
using superpack::test::rejected_at;
using superpack::test::check_tampered_bound_rejected;
using Document = nlohmann::json;

const Document& density_certificate() {
    static const Document document = [] {
        const Rational p = superpack::parse_rational("0.6");
        const superpack::DoubleField field;
        const auto lattice = superpack::enclose_family(Family::D14, p, field);
        return Document::parse(superpack::family_certificate(lattice, p, field, 15).dump());
    }();
    return document;
}

Document audit(const std::string& hi, int pieces, int depth) {
    superpack::AuditRange range = superpack::claimed_audit_range(Family::D14);
    range.hi = superpack::parse_rational(hi);
    range.breaks.clear();
    const auto result = superpack::audit_family(Family::D14, range, superpack::AuditSettings{pieces, depth});
    return Document::parse(superpack::audit_certificate(result).dump());
}

}  // namespace

TEST_CASE("D14 density certificate: valid, a packing density with 14 contacts, cited to Dostert and Vallentin") {
    const Document& document = density_certificate();
    const auto report = verify_document(document);
    REQUIRE(report.verdict == Verdict::valid);
    const std::string text = report.rendered_claim;
    CHECK(text.find("Dostert and Vallentin, New dense superball packings in three dimensions") != std::string::npos);
    CHECK(text.find("14 contacts") != std::string::npos);
    CHECK(text.find("of packing density phi") != std::string::npos);
    CHECK(document["claim"]["data"]["contacts"] == 14);
}

TEST_CASE("D14 density certificate: changing a digit of a bound is rejected at a proof step") {
    const Document& original = density_certificate();
    std::vector<std::string> bounds;
    collect_bounds(original["claim"], "/claim", bounds);
    collect_bounds(original["proof"], "/proof", bounds);
    REQUIRE(bounds.size() > 100);
    // The bounds of x and phi in the claim and eight of the proof's, spread over the partition
    // (it holds thousands; each replay of a claim bound costs the whole partition, 0.3 s).
    std::vector<std::string> chosen;
    for (const std::string& bound : bounds)
        if (bound.rfind("/claim/data/parameters/x", 0) == 0 || bound.rfind("/claim/data/phi", 0) == 0) chosen.push_back(bound);
    const std::size_t claim_bounds = chosen.size();
    std::vector<std::string> proof_bounds;
    for (const std::string& bound : bounds)
        if (bound.rfind("/proof", 0) == 0) proof_bounds.push_back(bound);
    for (std::size_t k = 0; k < 8; ++k) chosen.push_back(proof_bounds[k * proof_bounds.size() / 8]);
    REQUIRE(claim_bounds == 4);
    long tampered = 0;
    for (const std::string& bound : chosen) {
        check_tampered_bound_rejected(original, bound);
        ++tampered;
    }
    CHECK(tampered == 12);
}

TEST_CASE("D14 density certificate: a missing case, another family, p beyond p*_o, 12 contacts are rejected") {
    const Document& original = density_certificate();
    Document without_case = original;
    without_case["proof"]["parameters"]["cases"][0]["cases"].erase(1);
    CHECK(rejected_at(without_case) == "proof.parameters.cases[0].cases");
    Document o1 = original;  // the same proof read as O1's: a (q, s) partition is expected
    o1["claim"]["data"]["family"] = o1["inputs"]["family"] = "O1";
    CHECK(verify_document(o1).verdict != Verdict::valid);
    Document beyond = original;  // no root on the branch at p = 4/5: the boxes fail
    beyond["inputs"]["p"] = beyond["claim"]["data"]["p"] = "4/5";
    beyond["inputs"]["p_decimal"] = "0.8";
    auto report = verify_document(beyond);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.parameters", 0) == 0);
    Document outside = original;  // beyond the domain
    outside["inputs"]["p"] = outside["claim"]["data"]["p"] = "11/10";
    CHECK(rejected_at(outside) == "inputs.p");
    Document twelve = original;
    twelve["claim"]["data"]["contacts"] = 12;
    CHECK(rejected_at(twelve) == "claim.data.contacts");
    // The mirror root (x, z, y) stated as the branch: the checker's own choice differs.
    Document mirror = original;
    std::swap(mirror["claim"]["data"]["parameters"]["y"], mirror["claim"]["data"]["parameters"]["z"]);
    CHECK(rejected_at(mirror) == "claim.data.parameters.y");
}

TEST_CASE("D14 family lattice check at p = 1/2 and an audit on [1/2, 0.55]: valid, 14 contacts, chain enforced") {
    const Rational half(1, 2);
    const superpack::DoubleField field;
    const auto lattice = superpack::enclose_family(Family::D14, half, field);
    const auto check = superpack::check_family_lattice(lattice, field.rational(half));
    const Document minkowski =
        Document::parse(superpack::family_lattice_check_certificate(lattice, check, half, field, 15).dump());
    const auto report = verify_document(minkowski);
    REQUIRE(report.verdict == Verdict::valid);
    CHECK(report.rendered_claim.find("with 14 contacts") != std::string::npos);

    const Document d14 = audit("0.55", 4, 2);
    const auto audited = verify_document(d14);
    REQUIRE(audited.verdict == Verdict::valid);
    CHECK(audited.rendered_claim.find("through Minkowski's (1/3, 1/6, 1/2)") != std::string::npos);
    const Document& pieces = d14["claim"]["data"]["pieces"];
    REQUIRE(pieces.size() >= 4);
    for (const Document& piece : pieces) {
        CHECK(piece["verdict"] == "packing");
        CHECK(piece["contacts"] == 14);
    }
    Document broken = d14;  // the first box removed and its piece undecided: the chain breaks
    broken["proof"]["pieces"][0]["parameters"] = nullptr;
    broken["proof"]["pieces"][0]["lattice"] = nullptr;
    broken["claim"]["data"]["pieces"][0] = Document{{"p", pieces[0]["p"]}, {"verdict", "undecided"}, {"reason", "test"}};
    CHECK(rejected_at(broken) == "proof.pieces[1].parameters");
    // The mirror root (x, z, y): its box holds exactly one root for every p of the piece, but
    // not the branch through (1/3, 1/6, 1/2): the link to the previous piece fails.
    Document mirror = d14;
    Document& box = mirror["proof"]["pieces"][1]["parameters"]["box"];
    std::swap(box[1], box[2]);
    CHECK(rejected_at(mirror) == "proof.pieces[1].parameters");
    Document contacts = d14;
    contacts["claim"]["data"]["pieces"][2]["contacts"] = 12;
    CHECK(rejected_at(contacts) == "claim.data.pieces[2].contacts");
}
