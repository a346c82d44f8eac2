// `superpack verify`: replays a certificate with the checker's own arithmetic.
//
// A claim kind is checked by one function registered under its name (ClaimKindRegistration
// in a file checker/claim_<kind>.cpp); the verifier checks the head of the file, then
// dispatches on claim.kind. Every check names its place in the document (a path such as
// proof.cases[1].cases[0]) so that a rejection says which step failed. A claim kind returns
// the claim sentence, rendered from what it verified; the certificate's claim.text must be
// that sentence, every "decimal" must be the checker's rendering of its exact ends, and every
// key must have been read by some step (document_check.hpp).
#pragma once
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "checker/core/json_reader.hpp"
#include "checker/core/real.hpp"

namespace superpack_checker {

using Json = nlohmann::json;

enum class Verdict { valid, invalid, malformed };
const char* to_string(Verdict verdict);

struct VerifyReport {
    Verdict verdict = Verdict::malformed;
    std::string path;     // the first failing step (empty when valid)
    std::string message;  // why it failed
    std::string claim_kind, claim_text;
    // The checker's sentence for the claim, from the values it verified. Set once the claim
    // kind's replay has passed, also when a later step rejects the file: claim.text is
    // compared last, so a report rejected at "claim.text" has passed every other check.
    std::string rendered_claim;
    long steps = 0;       // checks performed
    mpfr_prec_t precision = 0;
};

// What a replay may use besides the document: the directory of its file (a cover certificate
// names its parts by file names there; an in-memory document has none unless given) and the
// threads it may run (a cover verifies its parts in parallel).
struct VerifySettings {
    std::string directory;
    int threads = 1;
};

// A document, the text of a file, or a file: whatever cannot be read within the limits of
// checker/core/limits.hpp (NOTES.md 8.8), is not JSON, or is not a regular file is malformed, with
// one line saying why (and the path in the document where that applies).
VerifyReport verify_document(const Json& document, const VerifySettings& settings = {});
VerifyReport verify_text(const std::string& text);
VerifyReport verify_file(const std::string& path, int threads = 1);

// A certificate file read within the limits (a regular file of at most max_file_bytes), parsed
// by read_json; not ok, with one line saying why, otherwise.
JsonReading read_certificate_file(const std::string& path);

// Thrown inside a claim checker; the verifier turns it into the report.
struct Rejection {
    Verdict verdict;
    std::string path, message;
};

// What a claim checker gets: the precision, readers that validate as they read, and the
// step counter.
class Context {
public:
    // A context outside verify_document (a test or a cover reading values) has no producer: its
    // own precision stands in for the producer's, the strictest choice for check_encloses.
    Context(const Json& document, mpfr_prec_t precision, VerifySettings settings = {})
        : document_(document),
          precision_(precision),
          producer_precision_(precision),
          settings_(std::move(settings)),
          read_(std::make_shared<std::unordered_set<const Json*>>()) {}
    // The same document at another precision, sharing the record of what has been read.
    Context(const Context& other, mpfr_prec_t precision, mpfr_prec_t producer_precision)
        : document_(other.document_),
          precision_(precision),
          producer_precision_(producer_precision),
          settings_(other.settings_),
          read_(other.read_) {}
    const Json& document() const { return document_; }
    const VerifySettings& settings() const { return settings_; }
    mpfr_prec_t precision() const { return precision_; }
    // The certificate's "bits": the precision its stated enclosures were computed at, which sets
    // how much wider than the checker's own they may honestly be (check_encloses).
    mpfr_prec_t producer_precision() const { return producer_precision_; }
    long steps() const { return steps_; }
    void count_step() { ++steps_; }
    void count_steps(long steps) { steps_ += steps; }
    // The step being checked, named in the report if an evaluation leaves its domain.
    std::string current_step;

    [[noreturn]] void reject(const std::string& path, const std::string& message) const;
    [[noreturn]] void malformed(const std::string& path, const std::string& message) const;
    // Checks `condition` as one step; rejects with `message` at `path` when it fails.
    void require(bool condition, const std::string& path, const std::string& message);

    // Every value read through member (and the readers built on it) is recorded: a key of the
    // document that no step read is an unknown key (document_check.hpp).
    const Json& member(const Json& object, const std::string& key, const std::string& path) const;
    const Json* optional_member(const Json& object, const std::string& key) const;  // null when absent
    bool was_read(const Json& value) const { return read_->count(&value) != 0; }
    std::string string_at(const Json& object, const std::string& key, const std::string& path) const;
    // {"lo": "m*2^e", "hi": "m*2^e"}, read exactly; lo > hi is a rejection (an empty set).
    Real interval(const Json& node, const std::string& path);
    std::vector<Real> box(const Json& node, const std::string& path);
    mpq_class rational_at(const Json& object, const std::string& key, const std::string& path) const;

private:
    const Json& document_;
    mpfr_prec_t precision_;
    mpfr_prec_t producer_precision_;
    VerifySettings settings_;
    long steps_ = 0;
    std::shared_ptr<std::unordered_set<const Json*>> read_;
};

// The one reader of a JSON integer: a value in [lo, hi], else malformed at `path` ("expected an
// integer from lo to hi", naming `limit` when one is given). Compared as the JSON value's own type
// (nlohmann keeps a parsed non-negative integer as unsigned 64-bit): get<long>() would wrap
// 2^64 - 1 into -1, so a file could show one number and the checker use another.
long read_integer(const Context& context, const Json& node, const std::string& path, long lo, long hi,
                  const char* limit = nullptr);

// Replays the claim and returns its sentence, rendered from the values it verified.
using ClaimChecker = std::string (*)(const Json& claim, Context& context);
struct ClaimKindRegistration {
    ClaimKindRegistration(const char* kind, ClaimChecker checker);
};
std::vector<std::string> registered_claim_kinds();

}  // namespace superpack_checker
