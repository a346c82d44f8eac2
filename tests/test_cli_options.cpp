// Options out of their range are refused with the range, never replaced by a default or wrapped
// into range: --pieces, --depth, --seed (one range for every command), an empty --digits, and a
// critical --gap that could give no valid proof.
#include <string>

#include "cli_run.hpp"

namespace {

using superpack::test::check_refused_before_work;
using superpack::test::Run;
using superpack::test::run;

}  // namespace

TEST_CASE("audit --pieces and --depth: a value out of range is refused with the range, not taken for the default") {
    check_refused_before_work("audit --family C0", {{"--pieces 0", "--pieces: Value 0 not in range 1 to 5000"},
                                                    {"--depth -1", "--depth: Value -1 not in range 0 to 30"}});
}

TEST_CASE("--seed: one range, 0 to 2^32 - 1, for best, simulate and md; nothing wraps") {
    for (const std::string command : {"best --p 2", "simulate --p 2", "md --p 1 --n 2"})
        for (const std::string seed : {"-1", "4294967296", "18446744073709551616", "1e26", "''", "+1", "0x10"})
            check_refused_before_work(command, {{"--seed " + seed, "--seed: a whole number from 0 to 4294967295"}});
}

TEST_CASE("an empty --digits is refused, not taken for binary64") {
    for (const std::string command : {"density --family C0 --p 2", "check-lattice --family C0 --p 2", "best --p 2",
                                      "superdisk --p 2", "slopes", "crossover cubic", "report --p-values 2"})
        check_refused_before_work(command, {{"--digits ''", "--digits must be a whole number from 1 to"}});
}

TEST_CASE("critical --gap: a gap that puts T below V(K) is refused before the branch and bound, with the largest gap") {
    // At p = 2 the best lattice (C1) has phi = 0.8699: T = (1 - G) |det| >= V(K) needs G <= 0.1301.
    for (const std::string json : {"", " --json"}) {
        const Run result = run("critical --p 2 --gap 0.3" + json);
        INFO(result.err);
        CHECK(result.status == 2);
        CHECK(result.err.find("--gap 3/10 is too large at p = 2") != std::string::npos);
        CHECK(result.err.find("at most 1 - phi of the best lattice, 1.301e-01") != std::string::npos);
        CHECK(result.err.find("boxes evaluated") == std::string::npos);
        CHECK(result.err.find("internal error") == std::string::npos);
        if (!json.empty()) CHECK(nlohmann::json::parse(result.out).value("exit", -1) == 2);
    }
}
