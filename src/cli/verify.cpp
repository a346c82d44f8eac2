// superpack verify FILE [--json]: replays a certificate with the independent checker (checker/).
#include <memory>

#include "checker/verifier.hpp"
#include "common.hpp"

namespace superpack::cli {

namespace {

struct VerifyOptions {
    std::string file;
    bool json = false;
};

int run(const VerifyOptions& options) {
    using namespace superpack_checker;
    const VerifyReport report = verify_file(options.file);
    if (options.json) {
        Json document = base_header_json("verify");
        document["file"] = options.file;
        document["verdict"] = to_string(report.verdict);
        document["claim_kind"] = report.claim_kind;
        // The checker's sentence, rendered from what it verified (never the file's words).
        document["claim"] = report.rendered_claim.empty() ? Json(nullptr) : Json(report.rendered_claim);
        document["steps"] = report.steps;
        document["checker_bits"] = report.precision;
        if (report.verdict != Verdict::valid) {
            document["failing_step"] = report.path;
            document["message"] = report.message;
        }
        std::cout << document.dump(2) << "\n";
    } else if (report.verdict == Verdict::valid) {
        std::cout << "valid: " << report.rendered_claim << "\n  (" << report.steps << " steps checked with MPFI at "
                  << report.precision << " bits)\n";
    }
    const std::string where = report.path.empty() ? "" : " at " + report.path;
    if (report.verdict == Verdict::invalid)
        throw Failure(exit_invalid, "invalid certificate " + options.file + ": step" + where + " fails: " + report.message);
    if (report.verdict == Verdict::malformed)
        throw Failure(exit_usage, "unreadable certificate " + options.file + where + ": " + report.message);
    return exit_ok;
}

}  // namespace

void add_verify(CLI::App& app) {
    auto options = std::make_shared<VerifyOptions>();
    CLI::App* command = app.add_subcommand(
        "verify", "Replay a certificate with the independent checker (exit 0 valid, 1 invalid, 2 unreadable)");
    command->add_option("file", options->file, "the certificate (JSON)")->required();
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("verify", add_verify);
}  // namespace

}  // namespace superpack::cli
