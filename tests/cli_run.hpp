// Running the superpack binary as a user does, for the tests of the command line: the exit
// status, stdout and stderr of one command.
#pragma once
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

namespace superpack::test {

struct Run {
    int status;
    std::string out, err;
};

// Runs the binary with `arguments` (shell words) in `directory` (empty: the current one), with
// `environment` (shell assignments such as "PATH=/x") for it alone.
inline Run run(const std::string& arguments, const std::string& directory = "", const std::string& environment = "") {
    // stderr goes to an exclusive temporary file (mkstemp: no name another process can take).
    std::string err_path = (std::filesystem::temp_directory_path() / "superpack-test-stderr-XXXXXX").string();
    const int descriptor = mkstemp(err_path.data());
    REQUIRE(descriptor >= 0);
    close(descriptor);
    const std::string command = (directory.empty() ? "" : "cd '" + directory + "' && ") + environment + " " +
                                std::string(SUPERPACK_BINARY) + " " + arguments + " 2>" + err_path;
    Run result{0, "", ""};
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::array<char, 4096> buffer{};
    while (fgets(buffer.data(), buffer.size(), pipe)) result.out += buffer.data();
    const int status = pclose(pipe);
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream err(err_path);
    result.err.assign(std::istreambuf_iterator<char>(err), {});
    std::remove(err_path.c_str());
    return result;
}

// `run` under an address-space limit of `kib` KiB (ulimit -v), where memory runs out.
inline Run run_with_memory_limit(const std::string& arguments, long kib) {
    return run(arguments, "", "ulimit -v " + std::to_string(kib) + " &&");
}

// Each case (arguments, a piece of the message): `command arguments`, with and without --json,
// exits 2 with one line on stderr holding the piece, before the work starts (no "certifying"
// on stderr: simulate and md say that first), with stdout empty, or with --json one document
// whose "exit" is 2.
inline void check_refused_before_work(const std::string& command, const std::vector<std::pair<std::string, std::string>>& cases) {
    for (const auto& [arguments, needle] : cases) {
        for (const std::string json : {"", " --json"}) {
            INFO(command + " " + arguments + json);
            const Run result = run(command + " " + arguments + json);
            INFO(result.err);
            CHECK(result.status == 2);
            CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
            CHECK(result.err.find(needle) != std::string::npos);
            CHECK(result.err.find("certifying") == std::string::npos);
            if (json.empty()) CHECK(result.out.empty());
            else CHECK(nlohmann::json::parse(result.out, nullptr, false).value("exit", -1) == 2);
        }
    }
}

}  // namespace superpack::test
