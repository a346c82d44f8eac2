#include "superpack/arith/mpfr_bounds.hpp"
#include "superpack/cert/certificate.hpp"

#include <stdexcept>

#include "checker/verifier.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/arith/self_test.hpp"
#include "superpack/cert/atomic_file.hpp"
#include "superpack/cert/dyadic_text.hpp"

namespace superpack {

std::string dyadic_text(const mpfr_t x) {
    if (mpfr_zero_p(x)) return "0";
    if (!mpfr_number_p(x)) throw std::runtime_error("certificate: an endpoint is not a finite number");
    mpz_class mantissa;
    long exponent = mpfr_get_z_2exp(mantissa.get_mpz_t(), x);
    // The shortest form: strip the mantissa's trailing zero bits into the exponent.
    const unsigned long zeros = mpz_scan1(mantissa.get_mpz_t(), 0);
    mpz_fdiv_q_2exp(mantissa.get_mpz_t(), mantissa.get_mpz_t(), zeros);
    exponent += static_cast<long>(zeros);
    if (exponent == 0) return mantissa.get_str();
    return mantissa.get_str() + "*2^" + std::to_string(exponent);
}

namespace {

template <class I>
Json exact_interval(const I& x, long bits) {
    mpfr_t lo, hi;
    mpfr_inits2(bits, lo, hi, static_cast<mpfr_ptr>(nullptr));
    get_bounds(lo, hi, x);
    // The file's "0" has no sign; the decimal is rendered from the same unsigned zero.
    if (mpfr_zero_p(lo)) mpfr_set_zero(lo, 1);
    if (mpfr_zero_p(hi)) mpfr_set_zero(hi, 1);
    const DecimalEnclosure text = to_decimal(lo, hi, 17);
    Json result{{"lo", dyadic_text(lo)}, {"hi", dyadic_text(hi)}, {"decimal", "[" + text.lo + ", " + text.hi + "]"}};
    mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
    return result;
}

SelfTestReport passing_self_test() {
    SelfTestReport report = run_rounding_self_test();
    if (!report.passed)
        throw std::runtime_error("rounding self-test failed (" + report.failures.front() + "); no certificate written");
    return report;
}

}  // namespace

// binary64 endpoints are exact in 53 bits. A ball's ends mid +- rad may need more bits than
// its precision; 64 guard bits keep them exact in practice, and any rounding is outward.
Json exact_interval_json(const DInterval& x) { return exact_interval(x, 53); }
Json exact_interval_json(const Ball& x) { return exact_interval(x, x.precision() + 64); }

template <class Field>
Json certificate_head(const std::string& command, const Field& field, long digits) {
    const SelfTestReport report = passing_self_test();
    Json head{{"format", "superpack-certificate"}, {"format_version", certificate_format_version}};
    head.update(header_json(command, field, digits));
    head["rounding_self_test"] = Json{{"passed", report.passed}, {"checks", report.checks}};
    return head;
}

Json certificate_document(Json head, Json claim, Json inputs, Json proof, const std::string& directory, int threads) {
    // The text, which the checker renders, goes between the kind and the data.
    head["claim"] = Json{{"kind", claim["kind"]}, {"text", ""}, {"data", std::move(claim["data"])}};
    head["inputs"] = std::move(inputs);
    head["proof"] = std::move(proof);
    // claim.text is compared last: a rejection there means every other step passed.
    superpack_checker::VerifySettings settings;
    settings.directory = directory;
    settings.threads = threads;
    const superpack_checker::VerifyReport report = superpack_checker::verify_document(head, settings);
    const bool only_text = report.verdict == superpack_checker::Verdict::invalid && report.path == "claim.text";
    if (report.verdict != superpack_checker::Verdict::valid && !only_text)
        throw CertificateRejected("the checker rejects this certificate at " + (report.path.empty() ? "(head)" : report.path) +
                                  ": " + report.message);
    head["claim"]["text"] = report.rendered_claim;
    return head;
}

void write_certificate(const std::string& path, const Json& document) {
    passing_self_test();
    write_atomically(path, document.dump(1) + "\n");
}

template Json certificate_head(const std::string&, const DoubleField&, long);
template Json certificate_head(const std::string&, const BallField&, long);

}  // namespace superpack
