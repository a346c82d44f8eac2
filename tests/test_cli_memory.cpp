// Out of memory is an answer, exit 4 with one line ("undecided: out of memory") and with --json
// the error document, never an abort: in the main thread (the audit's JSON, whose destruction
// allocates) and where the branch and bound's threads cannot start.
#include <string>

#include "cli_run.hpp"
#include "scratch.hpp"

namespace {

using superpack::test::Run;
using superpack::test::run_with_memory_limit;

// Exit 4 and one line saying why: out of memory, or out of threads where a thread's stack did
// not fit.
void check_out_of_memory(const std::string& arguments, long kib) {
    for (const std::string json : {"", " --json"}) {
        INFO(arguments + json);
        const Run result = run_with_memory_limit(arguments + json, kib);
        INFO(result.err.substr(result.err.size() > 400 ? result.err.size() - 400 : 0));
        CHECK(result.status == 4);
        const std::string last = result.err.substr(result.err.rfind('\n', result.err.size() - 2) + 1);
        CHECK(last.find("undecided: out of memory") != std::string::npos);
        CHECK(result.err.find("terminate called") == std::string::npos);
        if (json.empty()) continue;
        const nlohmann::json document = nlohmann::json::parse(result.out, nullptr, false);
        CHECK(document.value("exit", -1) == 4);
        CHECK(document.value("error", std::string()).find("out of memory") != std::string::npos);
    }
}

}  // namespace

TEST_CASE("out of memory in the audit's JSON is exit 4 with one line, not an abort") {
    const superpack::test::Scratch scratch;
    check_out_of_memory("audit --family C0 --pieces 2000 --output-directory " + scratch.path, 250000);
}

TEST_CASE("worker threads that cannot start (their stacks do not fit) are exit 4 with one line, not an abort") {
    check_out_of_memory("critical --p 2 --gap 0.01 --threads 2 --max-boxes 3000", 40000);
}
