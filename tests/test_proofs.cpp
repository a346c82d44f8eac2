// `make test` replays every committed certificate in proofs/ with `superpack verify`
// (the independent checker), as a referee would.
#include <chrono>
#include <filesystem>
#include <iostream>

#include "support.hpp"

namespace {

std::vector<std::string> proof_files() {
    std::vector<std::string> files;
    const std::filesystem::path folder = std::filesystem::path(SUPERPACK_TEST_DATA) / ".." / ".." / "proofs";
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

int exit_status(const std::string& command) {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("every certificate in proofs/ is valid under superpack verify") {
    const std::vector<std::string> files = proof_files();
    REQUIRE(files.size() >= 5);  // the committed set is far larger: an empty glob must not pass
    const auto start = std::chrono::steady_clock::now();
    for (const std::string& file : files) {
        INFO(file);
        CHECK(exit_status(std::string(SUPERPACK_BINARY) + " verify '" + file + "' > /dev/null") == 0);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "proofs/: " << files.size() << " certificates replayed by superpack verify in " << seconds << " s\n";
}
