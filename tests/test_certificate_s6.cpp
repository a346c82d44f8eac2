// Certificates of the S6 family (superpack's six-pair lattice, NOTES.md 4.2): density and family
// lattice check verify, the checker's sentence says whose family it is, and tampering with a
// bound, a contact triple, a basis entry, the Krawczyk box or p is rejected naming the step.
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
        const Rational p(9, 10);
        const superpack::DoubleField field;
        const auto lattice = superpack::enclose_family(Family::S6, p, field);
        return Document::parse(superpack::family_certificate(lattice, p, field, 15).dump());
    }();
    return document;
}

const Document& check_certificate() {
    static const Document document = [] {
        const Rational p(17, 20);
        const superpack::DoubleField field;
        const auto lattice = superpack::enclose_family(Family::S6, p, field);
        const auto check = superpack::check_family_lattice(lattice, field.rational(p));
        return Document::parse(superpack::family_lattice_check_certificate(lattice, check, p, field, 15).dump());
    }();
    return document;
}

}  // namespace

TEST_CASE("S6 certificates: valid, a packing with 12 contacts, rendered as superpack's own family") {
    for (const Document* document : {&density_certificate(), &check_certificate()}) {
        const auto report = verify_document(*document);
        INFO(report.path << ": " << report.message);
        REQUIRE(report.verdict == Verdict::valid);
        const std::string text = report.rendered_claim;
        CHECK(text.find("the S6 lattice, superpack's own family (issue 12") != std::string::npos);
        CHECK(text.find("(1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 1, -1), (1, 0, -1), (1, -1, 0)") != std::string::npos);
        CHECK(text.find("with 12 contacts") != std::string::npos);
        CHECK((*document)["claim"]["data"]["contacts"] == 12);
        CHECK((*document)["proof"]["parameters"]["kind"] == "krawczyk");
        CHECK((*document)["proof"]["parameters"]["box"].size() == 15);
    }
    CHECK(verify_document(density_certificate()).rendered_claim.find("of packing density phi") != std::string::npos);
}

TEST_CASE("S6 density certificate: changing a digit of any bound is rejected at a proof step") {
    const Document& original = density_certificate();
    std::vector<std::string> bounds;
    collect_bounds(original["claim"], "/claim", bounds);
    collect_bounds(original["proof"], "/proof", bounds);
    // 15 parameters, volume, determinant, phi in the claim; the box and the root in the proof.
    CHECK(bounds.size() == 2 * (15 + 3 + 15 + 15));
    long tampered = 0;
    for (const std::string& bound : bounds) {
        check_tampered_bound_rejected(original, bound);
        ++tampered;
    }
    CHECK(tampered == 96);
}

TEST_CASE("S6 certificates: a triple, a basis entry, the box, p outside the domain are each rejected at their path") {
    for (const Document* original : {&density_certificate(), &check_certificate()}) {
        // The checker's own triples define S6: a changed or negated triple in the claim is refused.
        Document triple = *original;
        triple["claim"]["data"]["contact_pairs"][3] = Document::array({1, 1, 0});
        CHECK(rejected_at(triple) == "claim.data.contact_pairs[3]");
        Document negated = *original;
        negated["claim"]["data"]["contact_pairs"][5] = Document::array({-1, 1, 0});
        CHECK(rejected_at(negated) == "claim.data.contact_pairs[5]");
        Document dropped = *original;
        dropped["claim"]["data"]["contact_pairs"].erase(5);
        CHECK(rejected_at(dropped) == "claim.data.contact_pairs");
        // The box cut to its upper half in b_00: it no longer holds the KKT point.
        Document box = *original;
        Document& b00 = box["proof"]["parameters"]["box"][0];
        b00["lo"] = box["proof"]["parameters"]["root"][0]["hi"];  // its decimal is checked after the proof
        CHECK(rejected_at(box).rfind("proof.parameters", 0) == 0);
        // A box with six multipliers missing: not the KKT system of the six pairs.
        Document short_box = *original;
        for (int k = 0; k < 6; ++k) {
            short_box["proof"]["parameters"]["box"].erase(9);
            short_box["proof"]["parameters"]["root"].erase(9);
        }
        CHECK(rejected_at(short_box) == "proof.parameters.box");
        // p outside ln3/ln4 < p < 1, in the inputs and the claim alike.
        for (const char* p : {"1", "79/100", "1/2"}) {
            Document outside = *original;
            outside["inputs"]["p"] = outside["claim"]["data"]["p"] = p;
            INFO("p = " << p);
            CHECK(rejected_at(outside) == "inputs.p");
        }
        // Another p inside the domain: the stored box holds no KKT point there.
        Document moved = *original;
        moved["inputs"]["p"] = moved["claim"]["data"]["p"] = "4/5";
        moved["inputs"]["p_decimal"] = "0.8";
        CHECK(rejected_at(moved).rfind("proof.parameters", 0) == 0);
        // The same proof read as another family's.
        Document d14 = *original;
        d14["claim"]["data"]["family"] = d14["inputs"]["family"] = "D14";
        CHECK(verify_document(d14).verdict != Verdict::valid);
    }
    // A basis entry moved off the checker's root (claim.data.parameters.b12 of the density claim).
    Document entry = density_certificate();
    entry["claim"]["data"]["parameters"]["b12"] = entry["claim"]["data"]["parameters"]["b11"];
    CHECK(rejected_at(entry) == "claim.data.parameters.b12");
    Document contacts = check_certificate();
    contacts["claim"]["data"]["contacts"] = 14;
    CHECK(rejected_at(contacts) == "claim.data.contacts");
}

TEST_CASE("an O0 audit certificate relabelled S6 is rejected: it states no contact pairs") {
    superpack::AuditRange range = superpack::claimed_audit_range(Family::O0);
    range.lo = Rational(9, 10);
    range.breaks.clear();
    const auto result = superpack::audit_family(Family::O0, range, superpack::AuditSettings{2, 0});
    Document audit = Document::parse(superpack::audit_certificate(result).dump());
    REQUIRE(verify_document(audit).verdict == Verdict::valid);
    audit["claim"]["data"]["family"] = audit["inputs"]["family"] = "S6";
    const auto report = verify_document(audit);
    CHECK(report.verdict == Verdict::malformed);
    CHECK(report.path == "claim.data");  // the missing member claim.data.contact_pairs
}
