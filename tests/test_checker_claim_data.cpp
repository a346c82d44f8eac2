// claim.data states what the checker re-derived (issue 44): every integer the checker reads is
// range-checked by one reader, so that 2^64 - 1 is not read as -1 (a false contact vector or
// witness that still verified) and -2^63 is never negated; and a stated enclosure shows what its
// sentence says of it, being at most a little wider than the checker's own. Each hostile edit is applied to a committed certificate of proofs/.
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

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

// Why a widened enclosure is refused (check_encloses), whatever its sentence says of it.
const std::string wider = "wider than the checker's own enclosure";

// The certificate with ends of exact intervals set (each pointer ".../lo" or ".../hi", each
// decimal rendered again as a forger would): the path at which it is invalid for `reason` (the
// start of the message), or what else it was.
std::string widened_rejected_at(Document document, const std::vector<std::pair<std::string, std::string>>& ends,
                                const std::string& reason) {
    for (const auto& [pointer, end] : ends) superpack::test::set_bound(document, pointer, end);
    const auto report = superpack_checker::verify_text(document.dump());
    INFO(to_string(report.verdict) << " at " << report.path << ": " << report.message);
    if (report.verdict != Verdict::invalid) return "(" + std::string(to_string(report.verdict)) + ")";
    return report.message.rfind(reason, 0) == 0 ? report.path : "(another reason at " + report.path + ")";
}

}  // namespace

TEST_CASE("an enclosure whose claim is a bound must show the bound itself, not only hold the checker's value") {
    // Each of these held the checker's value and was printed with its bound; each is now refused as
    // far wider than the checker's own enclosure, before proved_below's test of the bound (which
    // stays for an enclosure within the width allowed that reaches the bound).
    // The witness norm [1.97, 3.95]: it holds the true norm, and the sentence printed it with "< 2".
    CHECK(widened_rejected_at(committed_proof("lattice-O1-p0.6-overlapping"),
                              {{"/claim/data/witness/norm/hi", "8888999625333387*2^-51"}}, wider) == "claim.data.witness.norm");
    CHECK(widened_rejected_at(committed_proof("lattice-overlapping-p2"), {{"/claim/data/witness/norm/hi", "8556839292003947*2^-51"}},
                              wider) == "claim.data.witness.norm");
    CHECK(widened_rejected_at(committed_proof("audit-O0-p0.792481-1"),
                              {{"/claim/data/pieces/0/witness/norm/hi", "4503599623109453*2^-50"}},
                              wider) == "claim.data.pieces[0].witness.norm");
    // g(x) of a star-body witness point: "both < 1".
    CHECK(widened_rejected_at(committed_proof("star-lattice-quarter-p0.3-overlapping"),
                              {{"/claim/data/witness/values/0/hi", "5143650182532717*2^-52"}}, wider) == "claim.data.witness.values[0]");
    // A KKT multiplier: "all multipliers > 0".
    CHECK(widened_rejected_at(committed_proof("best-p0.6"), {{"/claim/data/multipliers/0/lo", "-1"}}, wider) ==
          "claim.data.multipliers[0]");
}

TEST_CASE("a stated value's enclosure is at most a little wider than the checker's own, whatever the claim") {
    // phi widened to [0.80, 1.61] holds the true density 0.8037..., and the sentence printed it.
    CHECK(widened_rejected_at(committed_proof("density-C0-p1.5"),
                              {{"/claim/data/phi/lo", "3602879701896397*2^-52"}, {"/claim/data/phi/hi", "7250795400066499*2^-52"}},
                              wider) == "claim.data.phi");
    // The crossover p*_c = 1.1508... widened to [1.1, 1.2].
    CHECK(widened_rejected_at(committed_proof("crossover-cubic"),
                              {{"/claim/data/p/lo", "2476979795053773*2^-51"}, {"/claim/data/p/hi", "5404319552844595*2^-52"}},
                              wider) == "claim.data.p");
    // phi*_c = 0.7597... with its upper end raised by 2^-29: 2^-28.6 of the value, beyond the
    // 2^-33 that the producer's rounding at 53 bits is allowed (limits.hpp).
    const Document cubic = committed_proof("crossover-cubic");
    CHECK(widened_rejected_at(cubic, {{"/claim/data/phi/hi", "1710641537864977*2^-51"}}, wider) == "claim.data.phi");
    // Raised by 2^-40 it is within that allowance: the replay passes, and only claim.text, which
    // prints the stated enclosure, is no longer the sentence.
    CHECK(widened_rejected_at(cubic, {{"/claim/data/phi/hi", "1710641533672721*2^-51"}}, "") == "claim.text");
    // The allowance follows the producer's bits: at 30 digits (132 bits) a raise by 2^-100 is too much.
    CHECK(widened_rejected_at(committed_proof("crossover-cubic-30digits"),
                              {{"/claim/data/phi/hi", "271061970865850241748090030067888178393186305*2^-148"}}, wider) == "claim.data.phi");
}
