// claim.data states what the checker re-derived (issue 44): every integer the checker reads is
// range-checked by one reader, so that 2^64 - 1 is not read as -1 (a false contact vector or
// witness that still verified) and -2^63 is never negated; and a stated enclosure shows what its
// sentence says of it. Each hostile edit is applied to a committed certificate of proofs/.
#include <cstdint>
#include <limits>

#include "checker/verifier.hpp"
#include "tamper.hpp"

namespace {

using superpack_checker::Verdict;
using Document = nlohmann::json;
using superpack::test::committed_proof;

// The three integers a 64-bit reader could wrap or negate into undefined behaviour.
const Document hostile_integers[] = {Document(std::numeric_limits<std::uint64_t>::max()),
                                     Document(Document::number_unsigned_t{1} << 63),
                                     Document(std::numeric_limits<std::int64_t>::min())};

// The certificate with the value at `pointer` replaced, replayed from its text as a file would
// be: the path of a malformed verdict, or what else it was.
std::string malformed_at(Document document, const std::string& pointer, const Document& value) {
    document[Document::json_pointer(pointer)] = value;
    const auto report = superpack_checker::verify_text(document.dump());
    INFO(pointer << " = " << value.dump() << ": " << to_string(report.verdict) << " at " << report.path << ": "
                 << report.message);
    return report.verdict == Verdict::malformed ? report.path : "(" + std::string(to_string(report.verdict)) + ")";
}

}  // namespace

TEST_CASE("an integer beyond 64 bits or -2^63 in a certificate is unreadable at its path, never wrapped") {
    const Document overlapping = committed_proof("lattice-O1-p0.6-overlapping"), density = committed_proof("density-O1-p0.6");
    const Document contacts = committed_proof("lattice-C0-p2"), audit = committed_proof("audit-C0-p1-10");
    const Document basis = committed_proof("lattice-minkowski-p0.5"), split = committed_proof("density-O1-p0.5-minkowski");
    for (const Document& value : hostile_integers) {
        // A witness coefficient -1 read as 2^64 - 1 made the sentence name a false witness.
        CHECK(malformed_at(overlapping, "/claim/data/witness/coefficients/1", value) == "claim.data.witness.coefficients[1]");
        CHECK(malformed_at(density, "/claim/data/witness/coefficients/2", value) == "claim.data.witness.coefficients[2]");
        // A contact vector listed with 2^64 - 1 for -1 was the checker's contact.
        CHECK(malformed_at(contacts, "/claim/data/contact_vectors/1/2", value) == "claim.data.contact_vectors[1][2]");
        CHECK(malformed_at(audit, "/claim/data/pieces/0/contact_vectors/3/1", value) ==
              "claim.data.pieces[0].contact_vectors[3][1]");
        CHECK(malformed_at(contacts, "/claim/data/contacts", value) == "claim.data.contacts");
        CHECK(malformed_at(basis, "/proof/reduction/transform/1/0", value) == "proof.reduction.transform[1][0]");
        CHECK(malformed_at(basis, "/proof/candidates/0/coefficients/0", value) == "proof.candidates[0].coefficients[0]");
        CHECK(malformed_at(split, "/proof/parameters/cases/0/dimension", value) == "proof.parameters.cases[0].dimension");
        CHECK(malformed_at(basis, "/digits", value) == "digits");
        CHECK(malformed_at(basis, "/bits", value) == "bits");
        CHECK(malformed_at(basis, "/format_version", value) == "format_version");
        CHECK(malformed_at(basis, "/rounding_self_test/checks", value) == "rounding_self_test.checks");
    }
    // The largest value in range is read as itself: a contact vector that is no contact is a
    // failed step, not an unreadable file.
    Document far = contacts;
    far["claim"]["data"]["contact_vectors"][1][2] = std::numeric_limits<std::int64_t>::max();
    const auto report = superpack_checker::verify_text(far.dump());
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path == "claim.data.contact_vectors");
}

namespace {

// The certificate with one end of an exact interval moved (its decimal rendered again): the path
// of an invalid verdict, or what else it was.
std::string widened_rejected_at(Document document, const std::string& pointer, const std::string& end) {
    superpack::test::set_bound(document, pointer, end);
    const auto report = superpack_checker::verify_text(document.dump());
    INFO(pointer << " = " << end << ": " << to_string(report.verdict) << " at " << report.path << ": " << report.message);
    return report.verdict == Verdict::invalid ? report.path : "(" + std::string(to_string(report.verdict)) + ")";
}

}  // namespace

TEST_CASE("an enclosure whose claim is a bound must show the bound itself, not only hold the checker's value") {
    // The witness norm [1.97, 3.95]: it holds the true norm, and the sentence printed it with "< 2".
    CHECK(widened_rejected_at(committed_proof("lattice-O1-p0.6-overlapping"), "/claim/data/witness/norm/hi",
                              "8888999625333387*2^-51") == "claim.data.witness.norm");
    CHECK(widened_rejected_at(committed_proof("lattice-overlapping-p2"), "/claim/data/witness/norm/hi",
                              "8556839292003947*2^-51") == "claim.data.witness.norm");
    CHECK(widened_rejected_at(committed_proof("audit-O0-p0.792481-1"), "/claim/data/pieces/0/witness/norm/hi",
                              "4503599623109453*2^-50") == "claim.data.pieces[0].witness.norm");
    // g(x) of a star-body witness point: "both < 1".
    CHECK(widened_rejected_at(committed_proof("star-lattice-quarter-p0.3-overlapping"), "/claim/data/witness/values/0/hi",
                              "5143650182532717*2^-52") == "claim.data.witness.values[0]");
    // A KKT multiplier: "all multipliers > 0".
    CHECK(widened_rejected_at(committed_proof("best-p0.6"), "/claim/data/multipliers/0/lo", "-1") == "claim.data.multipliers[0]");
}
