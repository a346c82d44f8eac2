// Certificates: versioned, self-describing JSON files that an independent checker
// (checker/, `superpack verify`) replays with its own arithmetic. NOTES.md section 8
// documents the format; this header is the producer's side of it.
//
// Every interval endpoint is written EXACTLY as "m*2^e" (integers m, e; "0" for zero), never
// as a rounded decimal; a decimal text sits beside it for people, which the checker renders
// again and compares. The claim sentence is the checker's: the producer keeps no template of
// it (certificate_document).
#pragma once
#include <stdexcept>
#include <string>

#include "superpack/problems/families/families.hpp"
#include "superpack/cert/output_header.hpp"

namespace superpack {

constexpr int certificate_format_version = 2;

// The independent checker rejected the certificate the producer assembled: a bug in one of
// them (a logic error, so that no handler of runtime errors takes it for an undecided result).
// Nothing is written; the CLI exits 1 with the message, which names the failing step.
struct CertificateRejected : std::logic_error {
    using std::logic_error::logic_error;
};

// {"lo": "m*2^e", "hi": "m*2^e", "decimal": "[lo, hi]"}: the interval's endpoints exactly.
Json exact_interval_json(const DInterval& x);
Json exact_interval_json(const Ball& x);

// The self-describing head of every certificate: format, format_version, tool, version,
// commit, command, backend, bits, digits, and the rounding self-test result.
// Throws std::runtime_error when the rounding self-test fails (no certificate without it).
template <class Field>
Json certificate_head(const std::string& command, const Field& field, long digits);

// Assembles the document from its head, the claim {"kind", "data"}, the exact inputs and the
// proof tree, replays it with the checker (checker/verifier.hpp) in memory and sets claim.text
// to the checker's rendering of the claim, so that a certificate written always verifies.
// Throws CertificateRejected ("the checker rejects this certificate at PATH: ...") otherwise.
// A cover certificate's parts are files in `directory`, replayed on `threads`.
Json certificate_document(Json head, Json claim, Json inputs, Json proof, const std::string& directory = "", int threads = 1);

// Runs the rounding self-test again (a library may have changed the mode since start-up) and
// writes atomically; throws std::runtime_error (naming the failed check) without touching
// `path` if it fails.
void write_certificate(const std::string& path, const Json& document);

}  // namespace superpack
