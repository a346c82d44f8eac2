// The files a command writes are checked before any work (README, "Files"): an empty name, two
// options naming one file and a target that cannot be written are refused at once, exit 2, the
// option named; nothing is left behind.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.hpp"
#include "scratch.hpp"

namespace {

using superpack::test::check_refused_before_work;
using superpack::test::Scratch;

bool is_empty(const std::string& directory) { return std::filesystem::is_empty(directory); }

}  // namespace

TEST_CASE("an empty output path is refused, naming the option, for every path option of every command") {
    const std::vector<std::pair<std::string, std::string>> commands = {
        {"density --family C0 --p 2", "--certificate"},  {"check-lattice --family C0 --p 2", "--certificate"},
        {"best --p 2", "--certificate"},                 {"best --scan 1:2:1", "--plot"},
        {"critical --p 2 --gap 0.01", "--certificate"},  {"audit --family C0", "--certificate"},
        {"audit --family C0", "--output-directory"},     {"crossover cubic", "--certificate"},
        {"slopes", "--certificate"},                     {"superdisk --p 2", "--certificate"},
        {"report --p-values 2", "--output"},
    };
    for (const auto& [command, option] : commands)
        check_refused_before_work(command, {{option + " ''", option + ": an empty name"}});
    for (const std::string command : {"simulate --p 2", "md --p 1 --n 2"})
        for (const std::string option : {"--xyz", "--mesh", "--png", "--certificate"})
            check_refused_before_work(command, {{option + " ''", option + ": an empty name"}});
}

TEST_CASE("two outputs naming one file are refused, however the name is spelt") {
    const Scratch scratch;
    const std::string file = scratch.path + "/packing", again = scratch.path + "/./sub/../packing";
    std::filesystem::create_directory(scratch.path + "/sub");
    check_refused_before_work("simulate --p 2", {{"--certificate " + file + " --xyz " + file, "names the same file as"}});
    check_refused_before_work("md --p 1 --n 2", {{"--xyz " + file + " --mesh " + again, "--mesh"}});
    // The audit's own file in --output-directory is an output too.
    check_refused_before_work("audit --family C0", {{"--output-directory " + scratch.path + " --certificate " + scratch.path +
                                                         "/audit-C0.json",
                                                     "names the same file as --certificate"}});
    std::filesystem::remove(scratch.path + "/sub");
    CHECK(is_empty(scratch.path));
}

TEST_CASE("a target no file can be created in is refused before the computation, naming the option") {
    // /proc takes no new file, though the directory exists and the name is free.
    check_refused_before_work("audit --family C0", {{"--certificate /proc/superpack-audit.json", "--certificate: cannot write"}});
    check_refused_before_work("critical --p 2 --gap 0.01", {{"--certificate /proc/superpack.json", "--certificate: cannot write"}});
    check_refused_before_work("simulate --p 2", {{"--xyz /proc/superpack.xyz", "--xyz: cannot write"}});
    check_refused_before_work("density --family C0 --p 2", {{"--certificate /proc/superpack.json", "--certificate"}});
    check_refused_before_work("report --p-values 2", {{"--output /proc/superpack.json", "--output: cannot write"}});
}

TEST_CASE("the check of a target leaves nothing behind") {
    const Scratch scratch;
    const superpack::test::Run written = superpack::test::run("density --family C0 --p 2 --certificate c0.json", scratch.path);
    CHECK(written.status == 0);
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(scratch.path)) names.push_back(entry.path().filename().string());
    CHECK(names == std::vector<std::string>{"c0.json"});
}
