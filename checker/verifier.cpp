#include "checker/verifier.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "checker/document_check.hpp"
#include "checker/json_reader.hpp"

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

// "m*2^e" or "m" (integers) into an MPFR number of exactly the bits m needs. False if not that form.
bool parse_dyadic(mpfr_t result, const std::string& text) {
    const std::size_t star = text.find("*2^");
    const std::string mantissa_text = text.substr(0, star);
    const std::size_t sign = (!mantissa_text.empty() && mantissa_text[0] == '-') ? 1 : 0;
    if (!all_digits(mantissa_text, sign) || mantissa_text.size() > 100000) return false;
    long exponent = 0;
    if (star != std::string::npos) {
        const std::string exponent_text = text.substr(star + 3);
        const std::size_t exponent_sign = (!exponent_text.empty() && exponent_text[0] == '-') ? 1 : 0;
        if (!all_digits(exponent_text, exponent_sign) || exponent_text.size() > 8) return false;
        exponent = std::stol(exponent_text);
    }
    const mpz_class mantissa(mantissa_text);
    const mpfr_prec_t bits = std::max<mpfr_prec_t>(2, static_cast<mpfr_prec_t>(mpz_sizeinbase(mantissa.get_mpz_t(), 2)));
    mpfr_set_prec(result, bits);
    mpfr_set_z_2exp(result, mantissa.get_mpz_t(), exponent, MPFR_RNDN);  // exact: bits suffice
    return true;
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
    if (!well_formed || text.size() > 10000) malformed(path + "." + key, "expected an exact rational \"a/b\", got \"" + text + "\"");
    mpq_class value(text);
    if (value.get_den() == 0) malformed(path + "." + key, "zero denominator");
    value.canonicalize();
    return value;
}

Real Context::interval(const Json& node, const std::string& path) {
    const std::string lo_text = string_at(node, "lo", path), hi_text = string_at(node, "hi", path);
    mpfr_t lo, hi;
    mpfr_inits2(2, lo, hi, static_cast<mpfr_ptr>(nullptr));
    const bool parsed = parse_dyadic(lo, lo_text) && parse_dyadic(hi, hi_text);
    Real result(precision_);
    const bool exact = parsed && exact_interval(result, lo, hi);
    const bool ordered = parsed && mpfr_cmp(lo, hi) <= 0;
    mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
    if (!parsed) malformed(path, "an endpoint is not of the form m*2^e");
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

VerifyReport verify_document(const Json& document) {
    VerifyReport report;
    long steps = 0;
    try {
        Context head(document, 128);
        if (head.string_at(document, "format", "") != "superpack-certificate")
            head.malformed("format", "not a superpack certificate");
        const Json& version = head.member(document, "format_version", "");
        if (!version.is_number_integer() || version.get<long>() != 2)
            head.malformed("format_version", "unsupported format version (this checker reads 2)");
        const Json& bits = head.member(document, "bits", "");
        if (!bits.is_number_integer() || bits.get<long>() < 2 || bits.get<long>() > 2000000)
            head.malformed("bits", "expected the producer's precision in bits");
        const Json& self_test = head.member(document, "rounding_self_test", "");
        const Json& claim = head.member(document, "claim", "");
        report.claim_kind = head.string_at(claim, "kind", "claim");
        report.claim_text = head.string_at(claim, "text", "claim");
        head.member(claim, "data", "claim");
        // The checker works 64 bits above the producer (at least 128), so that its own
        // enclosures are tighter than the ones it checks.
        report.precision = std::max<mpfr_prec_t>(128, bits.get<long>() + 64);
        Context context(head, report.precision);
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

VerifyReport verify_file(const std::string& path) {
    std::ifstream file(path);
    if (!file) {
        VerifyReport report;
        report.message = "cannot read " + path;
        return report;
    }
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    Json document;
    try {
        document = read_json(text);
    } catch (const Json::exception& error) {
        VerifyReport report;
        report.message = std::string("not JSON: ") + error.what();
        return report;
    } catch (const Rejection& rejection) {
        VerifyReport report;
        report.verdict = rejection.verdict;
        report.path = rejection.path;
        report.message = rejection.message;
        return report;
    }
    return verify_document(document);
}

}  // namespace superpack_checker
