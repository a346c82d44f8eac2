#include "checker/verifier.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "checker/core/document_check.hpp"
#include "checker/core/json_reader.hpp"
#include "checker/core/limits.hpp"

namespace superpack_checker {

const char* to_string(Verdict verdict) {
    switch (verdict) {
        case Verdict::valid: return "valid";
        case Verdict::invalid: return "invalid";
        case Verdict::malformed: return "malformed";
    }
    return "malformed";
}

namespace {

std::map<std::string, ClaimChecker>& registry() {
    static std::map<std::string, ClaimChecker> claims;
    return claims;
}

bool all_digits(const std::string& text, std::size_t from) {
    return from < text.size() && std::all_of(text.begin() + from, text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// "m*2^e" or "m" (integers) into an MPFR number of exactly the bits m needs. Empty when it is
// that form within the limits, else what is wrong.
std::string parse_dyadic(mpfr_t result, const std::string& text) {
    const std::size_t star = text.find("*2^");
    const std::string mantissa_text = text.substr(0, star);
    const std::size_t sign = (!mantissa_text.empty() && mantissa_text[0] == '-') ? 1 : 0;
    if (!all_digits(mantissa_text, sign)) return "an endpoint is not of the form m*2^e";
    if (mantissa_text.size() - sign > max_mantissa_digits)
        return "a mantissa of " + std::to_string(mantissa_text.size() - sign) + " digits exceeds the limit of " +
               std::to_string(max_mantissa_digits) + " (max_mantissa_digits)";
    long exponent = 0;
    if (star != std::string::npos) {
        const std::string exponent_text = text.substr(star + 3);
        const std::size_t exponent_sign = (!exponent_text.empty() && exponent_text[0] == '-') ? 1 : 0;
        if (!all_digits(exponent_text, exponent_sign)) return "an endpoint is not of the form m*2^e";
        if (exponent_text.size() - exponent_sign > max_exponent_digits)
            return "an exponent of " + std::to_string(exponent_text.size() - exponent_sign) + " digits exceeds the limit of " +
                   std::to_string(max_exponent_digits) + " (max_exponent_digits)";
        exponent = std::stol(exponent_text);
    }
    const mpz_class mantissa(mantissa_text, 10);  // base 10: base 0 would read a leading 0 as octal
    const mpfr_prec_t bits = std::max<mpfr_prec_t>(2, static_cast<mpfr_prec_t>(mpz_sizeinbase(mantissa.get_mpz_t(), 2)));
    mpfr_set_prec(result, bits);
    mpfr_set_z_2exp(result, mantissa.get_mpz_t(), exponent, MPFR_RNDN);  // exact: bits suffice
    return "";
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// The producer's precision, which sets the checker's (and so its cost): "bits" must be what
// "backend" and "digits" give (binary64 intervals: 53 bits at 15 digits; Arb balls:
// bits_for_digits(digits)), with digits within the command line's limit. Checked before
// anything is computed, so that a forged "bits" cannot make a small file run for minutes.
long producer_bits(const Context& head, const Json& document) {
    const std::string backend = head.string_at(document, "backend", "");
    const long digits = read_integer(head, head.member(document, "digits", ""), "digits", 1, max_digits, "max_digits");
    long expected = 0;
    if (starts_with(backend, "binary64-interval")) {
        if (digits != binary64_digits)
            head.malformed("digits", "a binary64 certificate has " + std::to_string(binary64_digits) + " digits, not " +
                                         std::to_string(digits));
        expected = binary64_bits;
    } else if (starts_with(backend, "arb-ball")) {
        expected = arb_bits_for_digits(digits);
    } else {
        head.malformed("backend", "unknown backend (this checker reads binary64-interval and arb-ball)");
    }
    const Json& bits = head.member(document, "bits", "");
    if (read_integer(head, bits, "bits", 1, max_bits) != expected)
        head.malformed("bits", "expected " + std::to_string(expected) + " bits for the backend at " + std::to_string(digits) +
                                   " digits, got " + bits.dump());
    return expected;
}

}  // namespace

ClaimKindRegistration::ClaimKindRegistration(const char* kind, ClaimChecker checker) { registry()[kind] = checker; }

std::vector<std::string> registered_claim_kinds() {
    std::vector<std::string> kinds;
    for (const auto& entry : registry()) kinds.push_back(entry.first);
    return kinds;
}

void Context::reject(const std::string& path, const std::string& message) const {
    throw Rejection{Verdict::invalid, path, message};
}
void Context::malformed(const std::string& path, const std::string& message) const {
    throw Rejection{Verdict::malformed, path, message};
}
void Context::require(bool condition, const std::string& path, const std::string& message) {
    ++steps_;
    if (!condition) reject(path, message);
}

const Json& Context::member(const Json& object, const std::string& key, const std::string& path) const {
    if (!object.is_object() || !object.contains(key)) malformed(path, "missing \"" + key + "\"");
    const Json& value = object[key];
    read_->insert(&value);
    return value;
}

const Json* Context::optional_member(const Json& object, const std::string& key) const {
    return object.is_object() && object.contains(key) ? &member(object, key, "") : nullptr;
}

std::string Context::string_at(const Json& object, const std::string& key, const std::string& path) const {
    const Json& value = member(object, key, path);
    if (!value.is_string()) malformed(path + "." + key, "expected a string");
    return value.get<std::string>();
}

mpq_class Context::rational_at(const Json& object, const std::string& key, const std::string& path) const {
    const std::string text = string_at(object, key, path);
    const std::size_t slash = text.find('/');
    const std::size_t sign = (!text.empty() && text[0] == '-') ? 1 : 0;
    const bool well_formed = slash == std::string::npos
                                 ? all_digits(text, sign)
                                 : all_digits(text.substr(0, slash), sign) && all_digits(text.substr(slash + 1), 0);
    if (text.size() > max_rational_characters)
        malformed(path + "." + key, "a rational of " + std::to_string(text.size()) + " characters exceeds the limit of " +
                                        std::to_string(max_rational_characters) + " (max_rational_characters)");
    if (!well_formed) malformed(path + "." + key, "expected an exact rational \"a/b\", got \"" + text + "\"");
    mpq_class value(text, 10);  // base 10: base 0 would read a leading 0 as octal
    if (value.get_den() == 0) malformed(path + "." + key, "zero denominator");
    value.canonicalize();
    return value;
}

long read_integer(const Context& context, const Json& node, const std::string& path, long lo, long hi, const char* limit) {
    bool in_range = false;
    if (node.is_number_unsigned()) {
        const std::uint64_t value = node.get<std::uint64_t>();
        in_range = hi >= 0 && value <= static_cast<std::uint64_t>(hi) && (lo <= 0 || value >= static_cast<std::uint64_t>(lo));
    } else if (node.is_number_integer()) {
        const std::int64_t value = node.get<std::int64_t>();
        in_range = lo <= value && value <= hi;
    }
    if (!in_range)
        context.malformed(path, "expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                                    (limit ? std::string(" (") + limit + ")" : std::string()) + ", got " + node.dump());
    return node.get<long>();  // in [lo, hi], so the same value in either JSON type
}

Real Context::interval(const Json& node, const std::string& path) {
    const std::string lo_text = string_at(node, "lo", path), hi_text = string_at(node, "hi", path);
    mpfr_t lo, hi;
    mpfr_inits2(2, lo, hi, static_cast<mpfr_ptr>(nullptr));
    std::string failure = parse_dyadic(lo, lo_text);
    if (failure.empty()) failure = parse_dyadic(hi, hi_text);
    const bool parsed = failure.empty();
    Real result(precision_);
    const bool exact = parsed && exact_interval(result, lo, hi);
    const bool ordered = parsed && mpfr_cmp(lo, hi) <= 0;
    mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
    if (!parsed) malformed(path, failure);
    if (!ordered) reject(path, "lower end above upper end (an empty interval)");
    if (!exact) malformed(path, "an endpoint needs more than " + std::to_string(precision_) + " bits");
    return result;
}

std::vector<Real> Context::box(const Json& node, const std::string& path) {
    if (!node.is_array() || node.empty()) malformed(path, "expected a non-empty array of intervals");
    std::vector<Real> result;
    for (std::size_t k = 0; k < node.size(); ++k) result.push_back(interval(node[k], path + "[" + std::to_string(k) + "]"));
    return result;
}

VerifyReport verify_document(const Json& document, const VerifySettings& settings) {
    VerifyReport report;
    long steps = 0;
    try {
        Context head(document, min_precision, settings);
        // A document built in memory has not been through read_json's depth limit.
        const DepthExcess excess = find_depth_excess(document);
        if (excess.found) head.malformed(excess.path, excess.message);
        if (head.string_at(document, "format", "") != "superpack-certificate")
            head.malformed("format", "not a superpack certificate");
        if (read_integer(head, head.member(document, "format_version", ""), "format_version", 0,
                         std::numeric_limits<long>::max()) != 2)
            head.malformed("format_version", "unsupported format version (this checker reads 2)");
        const long bits = producer_bits(head, document);
        const Json& self_test = head.member(document, "rounding_self_test", "");
        const Json& claim = head.member(document, "claim", "");
        report.claim_kind = head.string_at(claim, "kind", "claim");
        report.claim_text = head.string_at(claim, "text", "claim");
        head.member(claim, "data", "claim");
        // The checker works 64 bits above the producer (at least 128), so that its own
        // enclosures are tighter than the ones it checks.
        report.precision = std::max<mpfr_prec_t>(min_precision, bits + guard_bits);
        Context context(head, report.precision, bits);
        const Json& passed = context.member(self_test, "passed", "rounding_self_test");
        context.require(passed.is_boolean() && passed.get<bool>(), "rounding_self_test.passed",
                        "the producer's rounding self-test did not pass");
        const auto checker = registry().find(report.claim_kind);
        if (checker == registry().end()) context.malformed("claim.kind", "unknown claim kind \"" + report.claim_kind + "\"");
        try {
            report.rendered_claim = checker->second(claim, context);
            check_document(context, document, report.claim_text, report.rendered_claim);
        } catch (const std::domain_error& error) {
            // An operation outside its domain (log of a box reaching 0, ...) means a stored box
            // is not what the claim needs: a failed step, reported as such.
            steps = context.steps();
            throw Rejection{Verdict::invalid, context.current_step.empty() ? "claim" : context.current_step,
                            std::string("evaluation outside its domain: ") + error.what()};
        } catch (const std::exception& error) {
            // Anything else thrown while reading the claim (a JSON value of another type than a
            // step expects, text that is not a number) is a value the checker cannot read: the
            // file is unreadable there, never an internal error.
            throw Rejection{Verdict::malformed, context.current_step.empty() ? "claim" : context.current_step,
                            std::string("a value the checker cannot read (") + error.what() + ")"};
        }
        steps = context.steps();
        report.verdict = Verdict::valid;
    } catch (const Rejection& rejection) {
        report.verdict = rejection.verdict;
        report.path = rejection.path;
        report.message = rejection.message;
    } catch (const Json::exception& error) {
        report.verdict = Verdict::malformed;
        report.message = error.what();
    }
    report.steps = steps;
    return report;
}

namespace {

VerifyReport unreadable(const std::string& path, const std::string& message) {
    VerifyReport report;
    report.path = path;
    report.message = message;
    return report;
}

VerifyReport verify_reading(const JsonReading& reading, const VerifySettings& settings = {}) {
    if (!reading.ok) return unreadable(reading.path, reading.message);
    return verify_document(reading.document, settings);
}

JsonReading unread(const std::string& message) {
    JsonReading reading;
    reading.message = message;
    return reading;
}

std::string size_message(std::uintmax_t bytes) {
    return "a file of " + std::to_string(bytes) + " bytes exceeds the limit of " + std::to_string(max_file_bytes) +
           " bytes (max_file_bytes)";
}

}  // namespace

VerifyReport verify_text(const std::string& text) {
    if (text.size() > max_file_bytes) return unreadable("", size_message(text.size()));
    return verify_reading(read_json(text));
}

JsonReading read_certificate_file(const std::string& path) {
    // What the file is, before it is opened: a directory opens as a stream that fails on the first read.
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (error) return unread("cannot read " + path + ": " + error.message());
    if (!std::filesystem::is_regular_file(status))
        return unread("cannot read " + path + ": " + (std::filesystem::is_directory(status) ? "a directory" : "not a regular file"));
    const std::uintmax_t bytes = std::filesystem::file_size(path, error);
    if (error) return unread("cannot read " + path + ": " + error.message());
    if (bytes > max_file_bytes) return unread(size_message(bytes));
    std::ifstream file(path, std::ios::binary);
    if (!file) return unread("cannot read " + path);
    try {
        return read_json(file);
    } catch (const std::exception& failure) {  // a read error of the stream
        return unread("cannot read " + path + ": " + failure.what());
    }
}

VerifyReport verify_file(const std::string& path, int threads) {
    VerifySettings settings;
    settings.directory = std::filesystem::path(path).parent_path().string();
    if (settings.directory.empty()) settings.directory = ".";
    settings.threads = threads;
    return verify_reading(read_certificate_file(path), settings);
}

}  // namespace superpack_checker
