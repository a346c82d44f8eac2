// superpack-verify FILE [--json] [--threads N]: replays a superpack certificate with the independent checker
// and says what it proved. Exit 0 valid, 1 invalid (naming the first failing step), 2 unreadable.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>

#include "checker/build_commit.hpp"
#include "checker/verifier.hpp"

namespace {

using namespace superpack_checker;
// Keys in the order written, as every superpack document has them.
using Document = nlohmann::ordered_json;

constexpr int exit_valid = 0, exit_invalid = 1, exit_unreadable = 2;

const char* const usage =
    "usage: superpack-verify [--json] [--threads N] [--] FILE\n"
    "Replays a superpack certificate with the independent checker (its own interval arithmetic on MPFR, its own formulas).\n"
    "  --json         print one JSON document on stdout\n"
    "  --threads N    files of a critical-lattice-cover replayed at once, 1 to 64 (default: the cores)\n"
    "Exit: 0 valid, 1 invalid (the first failing step is named), 2 unreadable or bad usage.\n";

int fail(bool json, int code, const std::string& message) {
    if (json) std::cout << Document{{"tool", "superpack-verify"}, {"error", message}, {"exit", code}}.dump(2) << "\n";
    std::cerr << "superpack-verify: " << message << "\n";
    return code;
}

// A directory, FIFO or device is no certificate: refused before reading (a FIFO would block).
std::string not_a_certificate(const std::string& path) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (status.type() == std::filesystem::file_type::not_found) return "no such file";
    if (error) return error.message();
    if (status.type() == std::filesystem::file_type::directory) return "a directory, not a file";
    if (status.type() != std::filesystem::file_type::regular) return "not a regular file";
    return "";
}

constexpr int max_threads = 64;

int run(const std::string& file, bool json, int threads) {
    const std::string refusal = not_a_certificate(file);
    if (!refusal.empty()) return fail(json, exit_unreadable, "unreadable certificate " + file + ": " + refusal);
    const VerifyReport report = verify_file(file, threads);
    const std::string where = report.path.empty() ? "" : " at " + report.path;
    if (json) {
        Document document{{"tool", "superpack-verify"}, {"version", SUPERPACK_VERSION}, {"commit", build_commit()},
                      {"command", "verify"}, {"file", file}, {"verdict", to_string(report.verdict)},
                      {"claim_kind", report.claim_kind}, {"claim", report.rendered_claim}, {"steps", report.steps},
                      {"checker_bits", report.precision}};
        if (report.verdict != Verdict::valid) {
            document["failing_step"] = report.path;
            document["message"] = report.message;
        }
        std::cout << document.dump(2) << "\n";
    } else if (report.verdict == Verdict::valid) {
        std::cout << "valid: " << report.rendered_claim << "\n  (" << report.steps << " steps checked with MPFR intervals at "
                  << report.precision << " bits)\n";
    }
    if (report.verdict == Verdict::invalid) {
        std::cerr << "superpack-verify: invalid certificate " << file << ": step" << where << " fails: " << report.message << "\n";
        return exit_invalid;
    }
    if (report.verdict == Verdict::malformed) {
        std::cerr << "superpack-verify: unreadable certificate " << file << where << ": " << report.message << "\n";
        return exit_unreadable;
    }
    return exit_valid;
}

}  // namespace

int main(int argc, char** argv) {
    std::string file;
    bool json = false, file_given = false, options_ended = false;
    int threads = static_cast<int>(std::max(1u, std::min<unsigned>(max_threads, std::thread::hardware_concurrency())));
    for (int k = 1; k < argc; ++k) {
        const std::string argument = argv[k];
        const bool option = !options_ended && !argument.empty() && argument[0] == '-';
        if (option && argument == "--") {
            options_ended = true;
        } else if (option && (argument == "--help" || argument == "-h")) {
            std::cout << usage;
            return exit_valid;
        } else if (option && argument == "--version") {
            std::cout << "superpack-verify " << SUPERPACK_VERSION << " (" << build_commit() << ")\n";
            return exit_valid;
        } else if (option && argument == "--json") {
            json = true;
        } else if (option && argument == "--threads") {
            const std::string value = k + 1 < argc ? argv[++k] : "";
            const bool digits = !value.empty() && value.size() <= 2 && value.find_first_not_of("0123456789") == std::string::npos;
            threads = digits ? std::stoi(value) : 0;
            if (threads < 1 || threads > max_threads)
                return fail(json, exit_unreadable, "--threads: 1 to " + std::to_string(max_threads) + ", got '" + value.substr(0, 20) + "'");
        } else if (option) {
            return fail(json, exit_unreadable, "unknown option '" + argument.substr(0, 100) + "' (see --help)");
        } else if (file_given) {
            return fail(json, exit_unreadable, "one certificate at a time (see --help)");
        } else {
            file = argument;
            file_given = true;
        }
    }
    if (!file_given) return fail(json, exit_unreadable, "no certificate given (see --help)");
    try {
        return run(file, json, threads);
    } catch (const std::exception& error) {
        return fail(json, exit_unreadable, std::string("cannot check ") + file + ": " + error.what());
    }
}
