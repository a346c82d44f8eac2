// superpack verify FILE [--json]: replays a certificate with the independent checker (checker/).
#include <filesystem>
#include <memory>

#include "checker/verifier.hpp"
#include "common.hpp"

namespace superpack::cli {

namespace {

struct VerifyOptions {
    std::string file;
    bool json = false;
};

// A directory, FIFO or device is no certificate: refused before reading (a FIFO would block).
void require_regular_file(const std::string& path) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (status.type() == std::filesystem::file_type::not_found)
        throw Failure(exit_usage, "unreadable certificate " + path + ": no such file");
    if (error) throw Failure(exit_usage, "unreadable certificate " + path + ": " + error.message());
    if (status.type() == std::filesystem::file_type::directory)
        throw Failure(exit_usage, "unreadable certificate " + path + ": a directory, not a file");
    if (status.type() != std::filesystem::file_type::regular)
        throw Failure(exit_usage, "unreadable certificate " + path + ": not a regular file");
}

int run(const VerifyOptions& options) {
    using namespace superpack_checker;
    require_regular_file(options.file);
    VerifyReport report;
    try {
        report = verify_file(options.file);
    } catch (const std::exception& error) {
        throw Failure(exit_usage, "unreadable certificate " + options.file + ": " + error.what());
    }
    if (options.json) {
        Json document = base_header_json("verify");
        document["file"] = options.file;
        document["verdict"] = to_string(report.verdict);
        document["claim_kind"] = report.claim_kind;
        document["claim"] = report.claim_text;
        document["steps"] = report.steps;
        document["checker_bits"] = report.precision;
        if (report.verdict != Verdict::valid) {
            document["failing_step"] = report.path;
            document["message"] = report.message;
        }
        print_json(document);
    } else if (report.verdict == Verdict::valid) {
        std::cout << "valid: " << report.claim_text << "\n  (" << report.steps << " steps checked with MPFI at "
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
