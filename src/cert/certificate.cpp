#include "superpack/arith/mpfr_bounds.hpp"
#include "superpack/cert/certificate.hpp"

#include <stdexcept>

#include "checker/verifier.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/arith/exact_ends.hpp"
#include "superpack/arith/self_test.hpp"
#include "superpack/cert/atomic_file.hpp"

namespace superpack {

namespace {

template <class I>
Json exact_interval(const I& x) {
    const ExactEnds ends(x);
    const DecimalEnclosure text = to_decimal(ends.lo(), ends.hi(), 17);
    return Json{{"lo", dyadic_text(ends.lo())}, {"hi", dyadic_text(ends.hi())}, {"decimal", "[" + text.lo + ", " + text.hi + "]"}};
}

SelfTestReport passing_self_test() {
    SelfTestReport report = run_rounding_self_test();
    if (!report.passed)
        throw std::runtime_error("rounding self-test failed (" + report.failures.front() + "); no certificate written");
    return report;
}

}  // namespace

Json exact_interval_json(const DInterval& x) { return exact_interval(x); }
Json exact_interval_json(const Ball& x) { return exact_interval(x); }

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
