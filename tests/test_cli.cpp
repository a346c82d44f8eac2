// The command line as a user meets it: exit codes, one-line errors, one JSON document.
#include <array>
#include <cstdio>
#include <memory>

#include "support.hpp"

namespace {

struct Run {
    int status;
    std::string out, err;
};

Run run(const std::string& arguments) {
    const std::string err_path = std::tmpnam(nullptr);
    const std::string command = std::string(SUPERPACK_BINARY) + " " + arguments + " 2>" + err_path;
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

double width_of(const nlohmann::json& enclosure) {
    // Decimal strings with up to hundreds of digits: compare via a 600-digit parse.
    superpack::Ball lo(2100), hi(2100);
    arb_set_str(lo.get(), enclosure["lo"].get<std::string>().c_str(), 2100);
    arb_set_str(hi.get(), enclosure["hi"].get<std::string>().c_str(), 2100);
    return superpack::mid_double(hi - lo);
}

}  // namespace

TEST_CASE("bad input: one line on stderr, exit 2, nothing on stdout") {
    for (const char* arguments : {"density --family C0 --p 0", "density --family C0 --p -1", "density --family C0 --p abc",
                                  "density --family C9 --p 2", "density --family C0 --p 0.9", "density --family O0 --p 1.5",
                                  "density --family O1 --p 0.4", "density --family C0 --p 2 --digits 0",
                                  "density --family C0 --p 2 --digits many", "density --family C0 --p 2 --digits 1000000",
                                  "density --p 2", "nosuchcommand"}) {
        INFO(arguments);
        const Run result = run(arguments);
        CHECK(result.status == 2);
        CHECK(result.out.empty());
        CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
        CHECK(result.err.find("error") != std::string::npos);
    }
}

TEST_CASE("density --json: one document with the contract's names and widths") {
    const Run result = run("density --family C0 --p 1.5 --json");
    REQUIRE(result.status == 0);
    const auto document = nlohmann::json::parse(result.out);
    for (const char* key : {"tool", "version", "command", "family", "p", "digits", "volume", "parameters", "basis", "phi"})
        CHECK(document.contains(key));
    CHECK(document["parameters"].contains("s"));
    CHECK(document["basis"].size() == 3);
    CHECK(width_of(document["phi"]) <= 1e-12);
    const auto thirty = nlohmann::json::parse(run("density --family C0 --p 1.5 --digits 30 --json").out);
    CHECK(width_of(thirty["phi"]) <= 1e-30);
    CHECK(thirty["digits"] == 30);
    const Run three_hundred = run("density --family C0 --p 1.5 --digits 300 --json");
    REQUIRE(three_hundred.status == 0);
    CHECK(width_of(nlohmann::json::parse(three_hundred.out)["phi"]) <= 1e-300);
}

TEST_CASE("a certified impossibility exits 3 and still prints its document") {
    const Run result = run("density --family O1 --p 1 --json");
    CHECK(result.status == 3);
    const auto document = nlohmann::json::parse(result.out);
    CHECK(document["status"] == "no_lattice");
    CHECK(document["roots"].size() == 1);
}

TEST_CASE("every subcommand has --help") {
    for (const char* command : {"density", "report"}) {
        const Run result = run(std::string(command) + " --help");
        CHECK(result.status == 0);
        CHECK(result.out.find("--") != std::string::npos);
    }
}
