// Runs `superpack ARGUMENTS --json` (the binary this benchmark was built beside) and returns the
// parsed document (discarded when the output is not JSON) and the wall time until its output ended.
#pragma once
#include <array>
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

struct CommandRun {
    nlohmann::json document;
    double seconds = 0;
};

inline CommandRun run_json(const std::string& arguments) {
    const std::string command = std::string(SUPERPACK_BINARY) + " " + arguments + " --json 2>/dev/null";
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    std::string output;
    std::array<char, 4096> buffer{};
    while (pipe && fgets(buffer.data(), buffer.size(), pipe.get())) output += buffer.data();
    CommandRun run;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.document = nlohmann::json::parse(output, nullptr, false);
    return run;
}
