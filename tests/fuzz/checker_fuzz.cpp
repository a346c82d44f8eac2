// The checker's mutation fuzz test (NOTES.md 8.8): seeded random mutations of every certificate
// in proofs/ (mutation.hpp), each replayed in-process by the checker, which this executable
// compiles with -fsanitize=address,undefined -fno-sanitize-recover=all (cmake/fuzz.cmake). The
// test fails on a crash or a sanitizer report (the process dies), on an exception out of the
// checker, and on an accepted mutation that states something false (truth.hpp).
//
// Environment: SUPERPACK_FUZZ_SEED (default 1); SUPERPACK_FUZZ_COUNT, mutations per certificate
// (default 28, two of each kind); SUPERPACK_FUZZ_SECONDS, a budget of processor time per
// certificate after which its remaining mutations are skipped (default: none); SUPERPACK_FUZZ_FILE, only the
// certificates whose name contains it. Mutation k of a file depends on the seed, the file name
// and k only, so a failure is reproduced by its seed, file and number.
//
// Usage: superpack_checker_fuzz PROOFS_DIRECTORY REFERENCE_JSON
#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "checker/verifier.hpp"
#include "mutation.hpp"
#include "truth.hpp"

namespace {

using superpack_checker::Verdict;
using superpack_fuzz::Json;
using superpack_fuzz::MutationKind;
using Clock = std::chrono::steady_clock;

double environment(const char* name, double fallback) {
    const char* value = std::getenv(name);
    return value && *value ? std::atof(value) : fallback;
}

std::string read(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), {}};
}

// FNV-1a: a seed per file that does not depend on the order of the directory listing.
std::uint32_t name_hash(const std::string& name) {
    std::uint32_t hash = 2166136261u;
    for (unsigned char c : name) hash = (hash ^ c) * 16777619u;
    return hash;
}

struct Counts {
    long mutations = 0, accepted = 0, invalid = 0, malformed = 0;
};

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }
// Processor time, for the budget: the same mutations run on a busy machine as on an idle one.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: superpack_checker_fuzz PROOFS_DIRECTORY REFERENCE_JSON\n";
        return 2;
    }
    std::cout << std::unitbuf;  // a sanitizer report ends the process: what was printed stays
    const auto seed = static_cast<long>(environment("SUPERPACK_FUZZ_SEED", 1));
    const auto count = static_cast<long>(environment("SUPERPACK_FUZZ_COUNT", 2 * superpack_fuzz::mutation_kinds));
    const double budget = environment("SUPERPACK_FUZZ_SECONDS", 0);
    const char* only = std::getenv("SUPERPACK_FUZZ_FILE");
    const Json references = Json::parse(read(argv[2]));

    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(argv[1]))
        if (entry.path().extension() == ".json" && (!only || entry.path().filename().string().find(only) != std::string::npos))
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());

    std::array<Counts, superpack_fuzz::mutation_kinds> counts{};
    std::vector<std::string> failures;
    const Clock::time_point start = Clock::now();
    for (const auto& path : files) {
        const std::string name = path.filename().string();
        const Json original = Json::parse(read(path));
        const superpack_fuzz::Sites sites(original);
        const std::vector<superpack_fuzz::Rule> rules = superpack_fuzz::rules_for(references, name);
        const std::uint32_t hash = name_hash(name);
        const Clock::time_point file_start = Clock::now();
        const double file_cpu = cpu_seconds();
        long done = 0;
        for (long k = 0; k < count && (budget <= 0 || cpu_seconds() - file_cpu < budget); ++k, ++done) {
            std::seed_seq sequence{static_cast<std::uint32_t>(seed), hash, static_cast<std::uint32_t>(k)};
            std::mt19937_64 random(sequence);
            const auto kind = static_cast<MutationKind>((k + hash + static_cast<std::uint32_t>(seed)) % superpack_fuzz::mutation_kinds);
            const superpack_fuzz::Mutation mutation = superpack_fuzz::mutate(original, sites, kind, random);
            const std::string label = name + " #" + std::to_string(k) + " " + to_string(kind) + " at " + mutation.where;
            Counts& tally = counts[static_cast<std::size_t>(kind)];
            ++tally.mutations;
            superpack_checker::VerifyReport report;
            try {
                report = superpack_checker::verify_text(mutation.text);
            } catch (const std::exception& error) {
                failures.push_back(label + ": an exception left the checker: " + error.what());
                continue;
            } catch (...) {
                failures.push_back(label + ": an exception left the checker");
                continue;
            }
            if (report.verdict == Verdict::invalid) ++tally.invalid;
            if (report.verdict == Verdict::malformed) ++tally.malformed;
            if (report.verdict != Verdict::valid) continue;
            ++tally.accepted;
            const std::string falsehood = superpack_fuzz::falsehood(original, Json::parse(mutation.text), rules);
            if (!falsehood.empty()) failures.push_back(label + ": accepted, but " + falsehood);
        }
        std::cout << name << ": " << done << " mutations in " << cpu_seconds() - file_cpu << " s (" << since(file_start)
                  << " s wall)\n";
    }

    std::cout << "\nseed " << seed << ", " << files.size() << " certificates, " << cpu_seconds() << " s (" << since(start)
              << " s wall)\n"
              << "kind              mutations  accepted  invalid  malformed\n";
    Counts total;
    for (int k = 0; k < superpack_fuzz::mutation_kinds; ++k) {
        const Counts& c = counts[static_cast<std::size_t>(k)];
        std::printf("%-16s %10ld %9ld %8ld %10ld\n", to_string(static_cast<MutationKind>(k)), c.mutations, c.accepted, c.invalid,
                    c.malformed);
        total.mutations += c.mutations;
        total.accepted += c.accepted;
        total.invalid += c.invalid;
        total.malformed += c.malformed;
    }
    std::printf("%-16s %10ld %9ld %8ld %10ld\n", "total", total.mutations, total.accepted, total.invalid, total.malformed);
    std::fflush(stdout);
    for (const std::string& failure : failures) std::cout << "FAILED: " << failure << "\n";
    if (files.empty() || total.mutations == 0) {
        std::cout << "FAILED: no certificate was mutated\n";
        return 1;
    }
    return failures.empty() ? 0 : 1;
}
