// Certificates of the family packing verdicts (NOTES.md 8.4): "family-lattice-check" (one p)
// and "audit" (pieces of p). The proofs/ files are valid and say what NOTES claims; tampering
// with a bound, a piece, a verdict, p or the range is rejected naming the step; the checker's
// contact identities agree with the producer's list; the CLI writes atomically and writes
// nothing when undecided.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "checker/claims/family_parameters.hpp"
#include "checker/formulas/equations.hpp"
#include "checker/formulas/equations_audit.hpp"
#include "checker/verifier.hpp"
#include "superpack/cert/audit_certificate.hpp"
#include "tamper.hpp"
#include "support.hpp"

namespace {

using superpack::Family;
using superpack::Rational;
using superpack_checker::Verdict;
using superpack_checker::verify_document;
using Document = nlohmann::json;

Document family_check(Family family, const std::string& p) {
    const Rational exact = superpack::parse_rational(p);
    const superpack::DoubleField field;
    const auto lattice = superpack::enclose_family(family, exact, field);
    const auto check = superpack::check_family_lattice(lattice, field.rational(exact));
    return Document::parse(superpack::family_lattice_check_certificate(lattice, check, exact, field, 15).dump());
}

Document audit(Family family, const std::string& lo, const std::string& hi, int pieces, int depth) {
    superpack::AuditRange range = superpack::claimed_audit_range(family);
    range.lo = superpack::parse_rational(lo);
    range.hi = superpack::parse_rational(hi);
    const auto result = superpack::audit_family(family, range, superpack::AuditSettings{pieces, depth});
    return Document::parse(superpack::audit_certificate(result).dump());
}

Document proof_file(const std::string& name) {
    std::ifstream in(std::string(SUPERPACK_TEST_DATA) + "/../../proofs/" + name);
    REQUIRE(in.good());
    return Document::parse(in);
}

using superpack::test::collect_bounds;
using superpack::test::check_tampered_bound_rejected;
using superpack::test::tamper_inward;

// Moves every exact bound under the given pointers inward (except those whose pointer holds
// `skip`) and requires each change to be rejected with a path; returns how many were changed.
long tamper_all(const Document& original, const std::vector<std::string>& roots, const std::string& skip = "") {
    std::vector<std::string> bounds;
    for (const std::string& root : roots) collect_bounds(original[Document::json_pointer(root)], root, bounds);
    REQUIRE(!bounds.empty());
    long changed = 0;
    for (const std::string& bound : bounds) {
        if (!skip.empty() && bound.find(skip) != std::string::npos) continue;
        ++changed;
        check_tampered_bound_rejected(original, bound);
    }
    return changed;
}

Rational rational(const Document& text) { return superpack::parse_rational(text.get<std::string>()); }

int exit_status(const std::string& arguments) {
    const int raw = std::system((std::string(SUPERPACK_BINARY) + " " + arguments + " >/dev/null 2>&1").c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

}  // namespace

TEST_CASE("proofs/: the family lattice-checks and audits are valid and say what NOTES 8.4 claims") {
    const Document c0 = proof_file("lattice-C0-p2.json");
    CHECK(c0["claim"]["kind"] == "family-lattice-check");
    CHECK(c0["claim"]["data"]["verdict"] == "packing");
    CHECK(c0["claim"]["data"]["contacts"] == 12);
    CHECK(verify_document(c0).verdict == Verdict::valid);
    const Document o0 = proof_file("lattice-O0-p0.85.json");
    CHECK(o0["claim"]["data"]["contacts"] == 12);
    CHECK(verify_document(o0).verdict == Verdict::valid);
    const Document o1 = proof_file("lattice-O1-p0.6-overlapping.json");
    CHECK(o1["claim"]["data"]["verdict"] == "overlapping");
    CHECK(o1["claim"]["data"]["witness"]["coefficients"] == Document::array({1, -1, -1}));
    CHECK(verify_document(o1).verdict == Verdict::valid);

    // The audits: which p are covered by which verdict.
    struct Expected {
        const char* file;
        const char* lo;
        const char* hi;
        std::size_t pieces;
    };
    for (const Expected& expected : {Expected{"audit-C0-p1-10.json", "1", "10", 18}, Expected{"audit-C1-p1-10.json", "1", "10", 18},
                                     Expected{"audit-O0-p0.792481-1.json", "792481/1000000", "1", 28},
                                     Expected{"audit-O1-p0.5-0.792482.json", "1/2", "396241/500000", 742}}) {
        INFO(expected.file);
        const Document document = proof_file(expected.file);
        CHECK(document["claim"]["kind"] == "audit");
        CHECK(document["claim"]["text"].get<std::string>().find("prove nothing") != std::string::npos);
        const Document& data = document["claim"]["data"];
        CHECK(data["range"]["lo"] == expected.lo);
        CHECK(data["range"]["hi"] == expected.hi);
        CHECK(data["pieces"].size() == expected.pieces);
        const auto report = verify_document(document);
        CHECK(report.verdict == Verdict::valid);
    }
    auto pieces = [](const char* file) { return proof_file(file)["claim"]["data"]["pieces"]; };
    for (const Document& piece : pieces("audit-C0-p1-10.json")) CHECK((piece["verdict"] == "packing" && piece["contacts"] == 12));
    for (const Document& piece : pieces("audit-C1-p1-10.json")) CHECK((piece["verdict"] == "packing" && piece["contacts"] == 12));
    // O0: packing with 12 contacts from 0.79248125048828125 (just above p*_o = 0.7924812503605...) to 1.
    for (const Document& piece : pieces("audit-O0-p0.792481-1.json"))
        if (rational(piece["p"]["lo"]) >= superpack::parse_rational("0.79248125048828125"))
            CHECK((piece["verdict"] == "packing" && piece["contacts"] == 12));
    // O1 (erratum, NOTES 9): overlapping with witness e1 - e2 - e3 on all of [0.508682, 0.780987].
    Rational covered_lo = -1, covered_hi = -1;
    for (const Document& piece : pieces("audit-O1-p0.5-0.792482.json")) {
        if (piece["verdict"] == "packing") FAIL("an O1 piece is a packing");
        if (piece["verdict"] != "overlapping") continue;
        CHECK(piece["witness"]["coefficients"] == Document::array({1, -1, -1}));
        if (covered_hi == rational(piece["p"]["lo"])) covered_hi = rational(piece["p"]["hi"]);
        else if (covered_lo < 0) covered_lo = rational(piece["p"]["lo"]), covered_hi = rational(piece["p"]["hi"]);
    }
    CHECK(covered_lo <= Rational(508682, 1000000));
    CHECK(covered_hi >= Rational(780987, 1000000));
    // ... and at a certified point of every piece of [1/2, 0.791991].
    for (const Document& piece : pieces("audit-O1-p0.5-0.792482.json")) {
        if (rational(piece["p"]["hi"]) > Rational(791991, 1000000)) break;
        CHECK(piece["verdict"] != "undecided");
        if (piece["verdict"] == "overlapping_at_point") {
            CHECK(piece["witness"]["coefficients"] == Document::array({1, -1, -1}));
            CHECK((rational(piece["p"]["lo"]) <= rational(piece["at"]) && rational(piece["at"]) <= rational(piece["p"]["hi"])));
        }
    }
}

TEST_CASE("the checker's contact identities: the paper's contact vectors and nothing else") {
    using superpack_checker::combination;
    using superpack_checker::contact_identity;
    using superpack_checker::family_forms;
    // S6's forms are its KKT system's (the nine entries as symbols, lattice_forms), not a paper's.
    CHECK_THROWS_AS(family_forms("S6"), std::invalid_argument);
    for (Family family : superpack::all_families()) {
        INFO(superpack::to_string(family));
        const auto forms = superpack_checker::lattice_forms(superpack::to_string(family));
        // Over a box of triples, the checker's identities (written from the paper as linear
        // forms) select exactly the producer's list (lattice.cpp, NOTES 5.4): two independent homes.
        std::set<superpack::Coefficients> identities;
        for (long a = 0; a <= 3; ++a)
            for (long b = (a == 0 ? 0 : -3); b <= 3; ++b)
                for (long c = (a == 0 && b == 0 ? 1 : -3); c <= 3; ++c)
                    if (!contact_identity(forms, combination(forms, {a, b, c})).empty()) identities.insert({a, b, c});
        const auto listed = superpack::family_contact_triples(family);
        CHECK(identities == std::set<superpack::Coefficients>(listed.begin(), listed.end()));
    }
    // The O1 erratum vector e1 - e2 - e3 and O0's 2e3 - e1 - e2 = (0, 0, 4c) follow from no equation.
    const auto o1 = family_forms("O1");
    CHECK(contact_identity(o1, combination(o1, {1, -1, -1})).empty());
    const auto o0 = family_forms("O0");
    CHECK(contact_identity(o0, combination(o0, {1, 1, -2})).empty());
    CHECK(contact_identity(family_forms("C0"), combination(family_forms("C0"), {1, 1, -1})).find("Eq. 2") == 0);
}

TEST_CASE("the checker's linear-form bases agree with its numeric bases of Eqs. 1, 5, 8, 11") {
    const mpfr_prec_t precision = 128;
    auto number = [&](const char* q) { return superpack_checker::rational(mpq_class(q), precision); };
    const auto s = number("3/20"), t = number("7/10"), c = number("2/5"), l = number("3/5"), q = number("1/7");
    auto compare = [&](const char* family, const superpack_checker::Matrix3& numeric, std::vector<superpack_checker::Real> values) {
        const auto forms = superpack_checker::family_forms(family);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const auto entry = superpack_checker::evaluate(forms.basis[i][j], values, precision);
                INFO(family << " row " << i << " column " << j);
                CHECK((superpack_checker::subset(entry, numeric[i][j]) && superpack_checker::subset(numeric[i][j], entry)));
            }
    };
    compare("C0", superpack_checker::c0_basis(s, t), {t, s});
    compare("C1", superpack_checker::c1_basis(s, t), {t, s});
    compare("O0", superpack_checker::o0_basis(c), {c});
    compare("O1", superpack_checker::o1_basis(q, s, l), {l, q, s});
}

TEST_CASE("family-lattice-check: changing a digit of any bound is rejected, naming a step") {
    long tampered = 0;
    // (O0 at 0.85 has no bound to change: its proof is an evaluation and its claim a count.)
    for (const auto& [family, p] : {std::pair{Family::C0, "2"}, {Family::C1, "1.1"}, {Family::O1, "0.6"}})
        tampered += tamper_all(family_check(family, p), {"/claim", "/proof"});
    std::cout << "family-lattice-check tamper: " << tampered << " single-digit changes of bounds, every one rejected\n";
}

TEST_CASE("family-lattice-check: a changed p, verdict, contact count or witness is rejected") {
    const Document c0 = family_check(Family::C0, "2");
    Document both = c0;
    both["inputs"]["p"] = both["claim"]["data"]["p"] = "21/10";
    auto report = verify_document(both);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.parameters", 0) == 0);
    Document input_only = c0;
    input_only["inputs"]["p"] = "21/10";
    CHECK(verify_document(input_only).path == "inputs.p");
    Document more = c0;
    more["claim"]["data"]["contacts"] = 14;
    CHECK(verify_document(more).path == "claim.data.contacts");
    Document fewer = c0;
    fewer["proof"]["lattice"]["contacts"].erase(0);
    CHECK(verify_document(fewer).path == "proof.lattice.contacts");
    Document bound = c0;
    bound["proof"]["lattice"]["coefficient_bound"] = Document::array({0, 0, 0});
    CHECK(verify_document(bound).path == "proof.lattice.coefficient_bound");

    const Document o1 = family_check(Family::O1, "0.6");
    Document packing = o1;
    packing["claim"]["data"]["verdict"] = "packing";
    packing["claim"]["data"]["contacts"] = 12;
    packing["claim"]["data"]["contact_vectors"] = Document::array();
    packing["proof"]["lattice"] = Document{{"kind", "enumeration"}, {"coefficient_bound", {3, 3, 3}}, {"contacts", Document::array()}};
    report = verify_document(packing);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path == "claim.data");  // (1, -1, -1) has norm < 2
    Document other_witness = o1;
    other_witness["claim"]["data"]["witness"]["coefficients"] = Document::array({1, 0, 0});  // norm exactly 2
    CHECK(verify_document(other_witness).verdict == Verdict::invalid);
    Document family = o1;
    family["claim"]["data"]["family"] = family["inputs"]["family"] = "C1";
    CHECK(verify_document(family).verdict != Verdict::valid);
}

TEST_CASE("audit: changing a digit of any bound is rejected, naming a step") {
    // O0 over its claimed range (overlap, the undecided piece at p*_o, packings) and C1 on [1, 2].
    long tampered = tamper_all(audit(Family::O0, "792481/1000000", "1", 16, 12), {"/claim", "/proof"});
    // The upper end of a C1 piece's Newton box is left out: over a wide piece of p the box is
    // loose ([0, 0.3] around s ~ 0.15), and a smaller box that still holds the root is another
    // valid proof of the same claim. Moving it below the root is rejected (next test).
    const Document c1 = audit(Family::C1, "1", "2", 8, 2);
    tampered += tamper_all(c1, {"/claim", "/proof"}, "/parameters/cases/0/box/0/hi");
    Document below_root = c1;
    below_root["proof"]["pieces"][0]["parameters"]["cases"][0]["box"][0]["hi"] =
        c1["proof"]["pieces"][0]["parameters"]["cases"][0]["root"][0]["lo"];
    const auto report = verify_document(below_root);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.pieces[0].parameters.cases[0]", 0) == 0);
    // (O1's witness norms: the next test. Its Krawczyk boxes are not tampered with digit by
    // digit: a slightly smaller box around the same root can still be a valid proof.)
    std::cout << "audit tamper: " << tampered << " single-digit changes of bounds, every one rejected\n";
}

TEST_CASE("audit: gaps, deleted proofs, claims over undecided pieces and broken continuation are rejected") {
    const Document o0 = audit(Family::O0, "792481/1000000", "1", 16, 12);
    const Document& pieces = o0["claim"]["data"]["pieces"];
    std::size_t undecided = 0, packing = 0, overlapping = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        if (pieces[k]["verdict"] == "undecided") undecided = k;
        if (pieces[k]["verdict"] == "packing") packing = k;
        if (pieces[k]["verdict"] == "overlapping") overlapping = k;
    }
    REQUIRE((undecided > 0 && packing > 0));
    Document gap = o0;
    gap["claim"]["data"]["pieces"].erase(3);
    gap["proof"]["pieces"].erase(3);
    CHECK(verify_document(gap).path == "claim.data.pieces[3].p");
    Document no_proof = o0;
    no_proof["proof"]["pieces"].erase(3);
    CHECK(verify_document(no_proof).path == "proof.pieces");
    Document last = o0;
    last["claim"]["data"]["pieces"].erase(pieces.size() - 1);
    last["proof"]["pieces"].erase(pieces.size() - 1);
    CHECK(verify_document(last).path == "claim.data.pieces");
    Document wider = o0;  // the claim about the piece at p*_o: packing, with a packing piece's proof
    wider["claim"]["data"]["pieces"][undecided] = pieces[packing];
    wider["claim"]["data"]["pieces"][undecided]["p"] = pieces[undecided]["p"];
    wider["proof"]["pieces"][undecided] = o0["proof"]["pieces"][packing];
    auto report = verify_document(wider);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.pieces[" + std::to_string(undecided) + "]", 0) == 0);
    Document unproved = o0;  // a verdict without its proof
    unproved["claim"]["data"]["pieces"][undecided] = pieces[packing];
    unproved["claim"]["data"]["pieces"][undecided]["p"] = pieces[undecided]["p"];
    CHECK(verify_document(unproved).path == "proof.pieces[" + std::to_string(undecided) + "].parameters");
    Document flipped = o0;
    flipped["claim"]["data"]["pieces"][overlapping] = pieces[packing];
    flipped["claim"]["data"]["pieces"][overlapping]["p"] = pieces[overlapping]["p"];
    flipped["proof"]["pieces"][overlapping] = o0["proof"]["pieces"][packing];
    CHECK(verify_document(flipped).verdict == Verdict::invalid);
    Document contacts = o0;
    contacts["claim"]["data"]["pieces"][packing]["contacts"] = 14;
    CHECK(verify_document(contacts).path == "claim.data.pieces[" + std::to_string(packing) + "].contacts");
    Document range = o0;
    range["inputs"]["range"]["lo"] = "7924/10000";
    CHECK(verify_document(range).path == "inputs.range");
    Document moved = o0;  // both ranges and the first piece moved below O0's domain
    moved["inputs"]["range"]["lo"] = moved["claim"]["data"]["range"]["lo"] = moved["claim"]["data"]["pieces"][0]["p"]["lo"] = "1/2";
    CHECK(verify_document(moved).path == "inputs.range");

    // O1: the branch is followed from p = 1/2; a piece without its box breaks the chain.
    static const Document o1 = audit(Family::O1, "1/2", "0.51", 10, 3);
    CHECK(verify_document(o1).verdict == Verdict::valid);
    const Document& o1_pieces = o1["claim"]["data"]["pieces"];
    std::size_t decided = 0;  // the first piece overlapping for every p
    while (decided < o1_pieces.size() && o1_pieces[decided]["verdict"] != "overlapping") ++decided;
    REQUIRE((decided > 0 && decided < o1_pieces.size()));
    REQUIRE(o1_pieces[0]["verdict"] == "overlapping_at_point");
    Document outside = o1;  // the point must lie in its piece
    outside["claim"]["data"]["pieces"][0]["at"] = o1_pieces[1]["p"]["hi"];
    CHECK(verify_document(outside).path == "claim.data.pieces[0].at");
    Document minkowski = o1;  // at p = 1/2 itself e1 - e2 - e3 has norm exactly 2: no overlap
    minkowski["claim"]["data"]["pieces"][0]["at"] = "1/2";
    report = verify_document(minkowski);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("claim.data.pieces[0].witness", 0) == 0);
    Document whole = o1;  // a point refutation is no refutation of the whole piece
    whole["claim"]["data"]["pieces"][0]["verdict"] = "overlapping";
    CHECK(verify_document(whole).path.rfind("claim.data.pieces[0].witness", 0) == 0);
    Document norm = o1;
    Document& witness = norm["claim"]["data"]["pieces"][decided]["witness"]["norm"];
    witness["hi"] = tamper_inward(witness["hi"].get<std::string>(), false);
    CHECK(verify_document(norm).path == "claim.data.pieces[" + std::to_string(decided) + "].witness.norm");
    Document broken = o1;
    broken["proof"]["pieces"][decided - 1]["parameters"] = nullptr;  // claimed itself: rejected there
    CHECK(verify_document(broken).path == "proof.pieces[" + std::to_string(decided - 1) + "].parameters");
    broken["claim"]["data"]["pieces"][decided - 1] = Document{{"p", o1_pieces[decided - 1]["p"]}, {"verdict", "undecided"}, {"reason", "test"}};
    CHECK(verify_document(broken).path == "proof.pieces[" + std::to_string(decided) + "].parameters");
    Document swapped = o1;  // the box of another piece: no unique root for this piece's p, or no link
    swapped["proof"]["pieces"][decided]["parameters"] = o1["proof"]["pieces"][o1_pieces.size() - 1]["parameters"];
    report = verify_document(swapped);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.pieces[", 0) == 0);
    Document late = o1;  // the chain must start at p = 1/2
    late["claim"]["data"]["pieces"].erase(0);
    late["proof"]["pieces"].erase(0);
    late["claim"]["data"]["range"]["lo"] = late["inputs"]["range"]["lo"] = o1_pieces[1]["p"]["lo"];
    report = verify_document(late);
    CHECK(report.verdict == Verdict::invalid);
}

TEST_CASE("audit and check-lattice --family --certificate on the command line") {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "superpack-test-audit-certificate";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder / "out");
    const std::string good = (folder / "O0.json").string(), none = (folder / "none.json").string();
    const std::string out = " --output-directory " + (folder / "out").string();
    // O0 has undecided pieces next to p*_o: exit 4 after writing the certificate of the decided ones.
    REQUIRE(exit_status("audit --family O0 --certificate " + good + out) == 4);
    CHECK(exit_status("verify " + good) == 0);
    // Atomic: the certificate and nothing else (no temporary file) beside it.
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) files += entry.is_regular_file();
    CHECK(files == 1);
    // Nothing decided (O0 on one piece holding p*_o, where (0, 0, 4c) has norm 2): exit 4, no file.
    CHECK(exit_status("audit --family O0 --p-range 0.7924812:0.7924813 --pieces 1 --depth 0 --certificate " + none + out) == 4);
    CHECK(!std::filesystem::exists(none));
    CHECK(exit_status("audit --certificate " + none + out) == 2);
    CHECK(exit_status("audit --family O1 --second-root --certificate " + none + out) == 2);
    CHECK(exit_status("audit --family O1 --p-range 0.6:0.61 --pieces 2 --depth 0 --certificate " + none + out) == 2);
    CHECK(!std::filesystem::exists(none));

    const std::string lattice = (folder / "C0.json").string();
    REQUIRE(exit_status("check-lattice --family C0 --p 2 --certificate " + lattice) == 0);
    CHECK(exit_status("verify " + lattice) == 0);
    CHECK(exit_status("check-lattice --family O1 --p 0.5 --certificate " + none) == 4);  // Minkowski: two near contacts no identity decides
    CHECK(!std::filesystem::exists(none));
    REQUIRE(exit_status("check-lattice --family O1 --p 0.6 --digits 30 --certificate " + lattice) == 0);
    CHECK(exit_status("verify " + lattice) == 0);
    std::filesystem::remove_all(folder);
}

TEST_CASE("S6 audit: the mean-value Krawczyk chain from 9/10 verifies; a shifted box, a gap, a range outside the domain, "
          "a broken chain and a wrong packing claim are rejected") {
    // 8 pieces of 1/8000: [0.8995, 0.9] walked down (pieces 0..3), [0.9, 0.9005] up (4..7).
    const Document s6 = audit(Family::S6, "8995/10000", "9005/10000", 8, 0);
    REQUIRE(s6["claim"]["data"]["pieces"].size() == 8);
    REQUIRE(verify_document(s6).verdict == Verdict::valid);
    CHECK(superpack::decided_pieces(s6) == 8);
    Document shifted = s6;
    shifted["proof"]["pieces"][5]["parameters"]["box"][0] = Document{{"lo", "31*2^-4"}, {"hi", "125*2^-6"}};  // [1.9375, 1.953125], b00 is 1.9206...
    CHECK(verify_document(shifted).path == "proof.pieces[5].parameters");
    Document gap = s6;
    gap["claim"]["data"]["pieces"].erase(6);
    gap["proof"]["pieces"].erase(6);
    CHECK(verify_document(gap).path == "claim.data.pieces[6].p");
    Document outside = s6;
    outside["claim"]["data"]["range"]["lo"] = outside["inputs"]["range"]["lo"] = "79/100";
    outside["claim"]["data"]["pieces"][0]["p"]["lo"] = "79/100";
    CHECK(verify_document(outside).path == "inputs.range");
    // A box dropped below 9/10: that piece and every piece further down lose the chain, and
    // their packing claims are rejected (the first of them in order, piece 0, is named).
    Document broken = s6;
    broken["proof"]["pieces"][2]["parameters"] = nullptr;
    CHECK(verify_document(broken).path == "proof.pieces[0].parameters");
    broken["claim"]["data"]["pieces"][0] = Document{{"p", s6["claim"]["data"]["pieces"][0]["p"]}, {"verdict", "undecided"}};
    broken["claim"]["data"]["pieces"][1] = Document{{"p", s6["claim"]["data"]["pieces"][1]["p"]}, {"verdict", "undecided"}};
    broken["proof"]["pieces"][0] = broken["proof"]["pieces"][1] = Document{{"parameters", nullptr}, {"lattice", nullptr}};
    CHECK(verify_document(broken).path == "proof.pieces[2].parameters");
    // The anchor moved off the point at 9/10: the first link fails, so no piece is on the chain.
    Document unanchored = s6;
    unanchored["proof"].erase("anchor");
    CHECK(verify_document(unanchored).path == "proof");
    Document contacts = s6;
    contacts["claim"]["data"]["pieces"][4]["contacts"] = 14;
    CHECK(verify_document(contacts).path == "claim.data.pieces[4].contacts");
    // A packing claimed over a piece moved past the piece the box was proved for.
    Document moved = s6;
    moved["claim"]["data"]["pieces"][7]["p"]["hi"] = moved["claim"]["data"]["range"]["hi"] =
        moved["inputs"]["range"]["hi"] = "91/100";
    CHECK(verify_document(moved).path.rfind("proof.pieces[7].parameters", 0) == 0);
}
