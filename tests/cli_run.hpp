// Running the superpack binary as a user does, for the tests of the command line: the exit
// status, stdout and stderr of one command.
#pragma once
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

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

}  // namespace superpack::test
