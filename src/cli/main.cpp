// superpack: certified enclosures for dense superball and superdisk packings.
#include <algorithm>
#include <filesystem>
#include <new>

#include "common.hpp"
#include "superpack/cert/atomic_file.hpp"
#include "superpack/cert/certificate.hpp"
#include "superpack/cert/version.hpp"

namespace {

using namespace superpack::cli;

// At most max_error_characters, on one line, cut at a character boundary of UTF-8.
std::string one_line(const std::string& text) {
    std::string line = text;
    std::replace(line.begin(), line.end(), '\n', ' ');
    std::replace(line.begin(), line.end(), '\r', ' ');
    if (line.size() <= max_error_characters) return line;
    std::size_t end = max_error_characters - 3;
    while (end > 0 && (static_cast<unsigned char>(line[end]) & 0xC0) == 0x80) --end;
    return line.substr(0, end) + "...";
}

struct Error {
    int code;
    std::string message;
};

// The subcommand named on the command line, for the header of an error document.
std::string command_name(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        for (const auto& entry : subcommand_registry())
            if (entry.first == argv[i]) return entry.first;
    return "superpack";
}

// One line on stderr; with --json also one document on stdout, unless the command printed its own.
int report(const Error& error, bool json, const std::string& command) {
    const std::string message = one_line((error.code == exit_internal ? "internal error: " : "") + error.message);
    std::cerr << one_line(std::string("superpack: ") + (error.code == exit_usage ? "error: " : "") + message) << "\n";
    if (json && !json_printed()) {
        superpack::Json document = superpack::base_header_json(command);
        document["error"] = message;
        document["exit"] = error.code;
        print_json(document);
    }
    return error.code;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"superpack: certified enclosures for dense superball and superdisk packings.\n"
                 "Every number printed is a rigorous interval [lo, hi].\n"
                 "Exit codes: 0 done, 1 invalid certificate (verify), 2 bad usage or input, 3 certified\n"
                 "impossibility, 4 undecided (at this precision), 5 internal error (a bug)."};
    app.require_subcommand(1);
    app.set_version_flag("--version", superpack::version());
    auto registry = subcommand_registry();
    std::sort(registry.begin(), registry.end());
    for (const auto& entry : registry) entry.second(app);
    const bool json = std::any_of(argv + 1, argv + argc, [](const char* argument) { return std::string(argument) == "--json"; });
    Error error{exit_ok, ""};
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForAllHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForVersion& version) {
        return app.exit(version);
    } catch (const CLI::ParseError& parse_error) {
        error = {exit_usage, parse_error.what()};
    } catch (const superpack::InputError& input_error) {
        error = {exit_usage, input_error.what()};
    } catch (const superpack::FileError& file_error) {
        error = {exit_usage, file_error.what()};
    } catch (const std::filesystem::filesystem_error& file_error) {
        error = {exit_usage, file_error.what()};
    } catch (const superpack::CertificateRejected& rejected) {
        error = {exit_invalid, std::string("no certificate written: ") + rejected.what()};
    } catch (const Failure& failure) {
        error = {failure.code, failure.what()};
    } catch (const std::domain_error& domain_error) {
        // A function's contract refused an enclosure of a legal input outside with_field (the audit's
        // binary64 pieces): undecided, not a crash.
        error = {exit_undecided, undecided_at_precision(domain_error.what(), 0, 0)};
    } catch (const std::bad_alloc&) {
        error = {exit_undecided, "undecided: out of memory"};
    } catch (const std::exception& bug) {
        error = {exit_internal, bug.what()};
    }
    if (error.code == exit_ok) return exit_ok;
    return report(error, json, command_name(argc, argv));
}
