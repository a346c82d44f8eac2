#include "command_line.hpp"

#include <algorithm>
#include <filesystem>
#include <new>
#include <system_error>

#include "common.hpp"
#include "memory_reserve.hpp"
#include "superpack/cert/atomic_file.hpp"
#include "superpack/cert/certificate.hpp"
#include "superpack/cert/version.hpp"
#include "superpack/render/render_error.hpp"

namespace superpack::cli {

namespace {

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

// The subcommand named on the command line, for the header of an error document.
std::string command_name(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        for (const auto& entry : subcommand_registry())
            if (entry.first == argv[i]) return entry.first;
    return "superpack";
}

// Parses and runs; the exceptions are mapped by run_command_line.
int parse_and_run(int argc, char** argv) {
    CLI::App app{"superpack: certified enclosures for dense superball and superdisk packings.\n"
                 "Every number printed is a rigorous interval [lo, hi].\n"
                 "Exit codes: 0 done, 1 invalid certificate (verify), 2 bad usage or input, 3 certified\n"
                 "impossibility, 4 undecided (at this precision), 5 internal error (a bug)."};
    app.require_subcommand(1);
    app.set_version_flag("--version", superpack::version());
    auto registry = subcommand_registry();
    std::sort(registry.begin(), registry.end());
    for (const auto& entry : registry) entry.second(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForAllHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForVersion& version) {
        return app.exit(version);
    }
    return exit_ok;
}

}  // namespace

CommandOutcome run_command_line(int argc, char** argv) {
    CommandOutcome outcome;
    outcome.command = command_name(argc, argv);
    outcome.json = std::any_of(argv + 1, argv + argc, [](const char* argument) { return std::string(argument) == "--json"; });
    forget_printed_json();
    const MemoryReserve reserve;
    const auto fail = [&outcome](int code, const std::string& message) {
        outcome.code = code;
        outcome.message = message;
    };
    try {
        outcome.code = parse_and_run(argc, argv);
    } catch (const CLI::ParseError& parse_error) {
        fail(exit_usage, parse_error.what());
    } catch (const InputError& input_error) {
        fail(exit_usage, input_error.what());
    } catch (const FileError& file_error) {
        fail(exit_usage, file_error.what());
    } catch (const std::filesystem::filesystem_error& file_error) {
        fail(exit_usage, file_error.what());
    } catch (const RenderError& render_error) {
        fail(exit_usage, render_error.what());
    } catch (const CertificateRejected& rejected) {
        fail(exit_invalid, std::string("no certificate written: ") + rejected.what());
    } catch (const Failure& failure) {
        fail(failure.code, failure.what());
    } catch (const std::domain_error& domain_error) {
        // The last line of defence against a bug: every driver call of a command goes through
        // within_contract (decided), so no command relies on this; a refusal that escapes one is
        // still undecided, not a crash.
        fail(exit_undecided, undecided_at_precision(domain_error.what(), 0, 0));
    } catch (const std::bad_alloc&) {
        fail(exit_undecided, "undecided: out of memory");
    } catch (const std::system_error& error) {
        // A thread that cannot start (pthread_create: EAGAIN, as under ulimit -v) is out of
        // resources like bad_alloc; any other system error is a bug.
        if (error.code() == std::errc::resource_unavailable_try_again)
            fail(exit_undecided, std::string("undecided: out of memory or threads (") + error.what() + ")");
        else
            fail(exit_internal, error.what());
    } catch (const std::exception& bug) {
        fail(exit_internal, bug.what());
    }
    if (outcome.code != exit_ok)
        outcome.message = one_line((outcome.code == exit_internal ? "internal error: " : "") + outcome.message);
    return outcome;
}

int report_failure(const CommandOutcome& outcome) {
    std::cerr << one_line(std::string("superpack: ") + (outcome.code == exit_usage ? "error: " : "") + outcome.message) << "\n";
    if (outcome.json && !json_printed()) {
        Json document = base_header_json(outcome.command);
        document["error"] = outcome.message;
        document["exit"] = outcome.code;
        print_json(document);
    }
    return outcome.code;
}

}  // namespace superpack::cli
