// Certificates: versioned, self-describing JSON files that an independent checker
// (checker/, `superpack verify`) replays with its own arithmetic. NOTES.md section 8
// documents the format; this header is the producer's side of it.
//
// Every interval endpoint is written EXACTLY as "m*2^e" (integers m, e; "0" for zero), never
// as a rounded decimal, so that the checker rereads bit for bit what was proved; a decimal
// text sits beside it for people only.
#pragma once
#include <string>

#include "superpack/problems/families.hpp"
#include "superpack/cert/output_header.hpp"

namespace superpack {

constexpr int certificate_format_version = 1;

// {"lo": "m*2^e", "hi": "m*2^e", "decimal": "[lo, hi]"}: the interval's endpoints exactly.
Json exact_interval_json(const DInterval& x);
Json exact_interval_json(const Ball& x);

// The self-describing head of every certificate: format, format_version, tool, version,
// commit, command, backend, bits, digits, and the rounding self-test result.
// Throws std::runtime_error when the rounding self-test fails (no certificate without it).
template <class Field>
Json certificate_head(const std::string& command, const Field& field, long digits);

// Assembles the document from its head, the claim {"kind", "text", "data"}, the exact
// inputs and the proof tree.
Json certificate_document(Json head, Json claim, Json inputs, Json proof);

// Runs the rounding self-test again (a library may have changed the mode since start-up) and
// writes atomically; throws std::runtime_error (naming the failed check) without touching
// `path` if it fails.
void write_certificate(const std::string& path, const Json& document);

}  // namespace superpack
