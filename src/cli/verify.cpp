// superpack verify FILE [--json] [--threads N]: runs the independent checker, superpack-verify, which is
// built beside this executable and shares no code with it (checker/).
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <vector>

#include "common.hpp"

namespace superpack::cli {

namespace {

struct VerifyOptions {
    std::string file;
    bool json = false;
    int threads = 0;  // 0: the checker's default, every core
};

// The directory this executable was started from.
std::string own_directory() {
    std::vector<char> buffer(4096);
    const ssize_t length = readlink("/proc/self/exe", buffer.data(), buffer.size() - 1);
    if (length <= 0) throw Failure(exit_usage, "error: cannot find the directory of superpack (/proc/self/exe)");
    const std::string path(buffer.data(), static_cast<std::size_t>(length));
    return path.substr(0, path.rfind('/'));
}

[[noreturn]] void run(const VerifyOptions& options) {
    const std::string checker = own_directory() + "/superpack-verify";
    std::vector<std::string> arguments{checker};
    if (options.json) arguments.push_back("--json");
    if (options.threads != 0) {  // the checker enforces its limit
        arguments.push_back("--threads");
        arguments.push_back(std::to_string(options.threads));
    }
    arguments.push_back("--");
    arguments.push_back(options.file);
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    argv.push_back(nullptr);
    std::cout.flush();
    execv(checker.c_str(), argv.data());
    throw Failure(exit_usage, "error: cannot run " + checker + ": " + std::strerror(errno));
}

}  // namespace

void add_verify(CLI::App& app) {
    auto options = std::make_shared<VerifyOptions>();
    CLI::App* command = app.add_subcommand(
        "verify", "Replay a certificate with the independent checker superpack-verify (exit 0 valid, 1 invalid, 2 unreadable)");
    command->add_option("file", options->file, "the certificate (JSON)")->required();
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    command->add_option("--threads", options->threads,
                        "files of a critical-lattice-cover replayed at once, 1 to 64 (default or 0: every core)");
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("verify", add_verify);
}  // namespace

}  // namespace superpack::cli
