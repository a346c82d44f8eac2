// The command line as a user meets it: exit codes, one-line errors, one JSON document.
#include <array>
#include <filesystem>
#include <cstdio>
#include <cstring>
#include <memory>

#include <sys/stat.h>

#include <stdlib.h>
#include <unistd.h>

#include "cli_run.hpp"
#include "scratch.hpp"
#include "support.hpp"
#include "superpack/arith/arb_access.hpp"

namespace {

using superpack::test::Run;
using superpack::test::run;

double width_of(const nlohmann::json& enclosure) {
    // Decimal strings with up to hundreds of digits: compare via a 600-digit parse.
    superpack::Ball lo(2100), hi(2100);
    arb_set_str(arb_of(lo), enclosure["lo"].get<std::string>().c_str(), 2100);
    arb_set_str(arb_of(hi), enclosure["hi"].get<std::string>().c_str(), 2100);
    return superpack::mid_double(hi - lo);
}

// A fresh empty directory, removed afterwards.
using superpack::test::Scratch;

std::size_t lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

// An error as the contract wants it: the exit code, one line on stderr (at most 300 characters
// and a newline) naming the problem, never "internal error"; with --json one document on stdout
// {"error": ..., "exit": code}.
void check_error(const std::string& arguments, int code, const std::string& needle, bool with_json = true) {
    INFO(arguments);
    const Run plain = run(arguments);
    INFO(plain.err);
    CHECK(plain.status == code);
    CHECK(lines(plain.err) == 1);
    CHECK(plain.err.size() <= 301);
    CHECK(plain.err.find("internal error") == std::string::npos);
    CHECK(plain.err.find(needle) != std::string::npos);
    if (!with_json) return;
    const Run json = run(arguments + " --json");
    CHECK(json.status == code);
    CHECK(lines(json.err) == 1);
    // Exactly one document: parse rejects a second one after the first.
    const nlohmann::json document = nlohmann::json::parse(json.out, nullptr, false);
    CHECK(document.is_object());
    if (!document.is_object()) return;
    CHECK(document.value("exit", -1) == code);
    CHECK(document.value("error", std::string()).find(needle) != std::string::npos);
    // `verify` runs the checker's own executable, which names itself.
    const bool verify = arguments.rfind("verify", 0) == 0;
    CHECK(document.value("tool", std::string()) == (verify ? "superpack-verify" : "superpack"));
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

TEST_CASE("critical: its limits are one-line errors, exit 2, before any computation") {
    for (const char* arguments : {"critical --p 0.5", "critical --p 11", "critical --p 1", "critical --p 2 --gap 0.5",
                                  "critical --p 2 --gap -0.1", "critical --p 2 --threads 0", "critical --p 2 --threads 65",
                                  "critical --p 2 --shard 3/2", "critical --p 2 --shard 0/169", "critical --p 2 --shard x",
                                  "critical --p 2 --max-boxes 0", "critical --gap 0.1", "critical --p 2 --around 0",
                                  "critical --p 2 --around 0.02", "critical --p 2 --around x", "critical --p 2 --split 9",
                                  "critical --p 2 --split 1 --around 1e-5", "critical --p 2 --split 1 --shard 0/337"}) {
        INFO(arguments);
        const Run result = run(arguments);
        CHECK(result.status == 2);
        CHECK(result.out.empty());
        CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
    }
}

TEST_CASE("critical with a budget too small: the whole answer printed, status undecided, exit 4") {
    const Run result = run("critical --p 2 --max-boxes 50 --json");
    CHECK(result.status == 4);
    const auto document = nlohmann::json::parse(result.out);
    CHECK(document["status"] == "undecided");
    CHECK(document["boxes"]["undecided_budget"].get<long>() > 0);
    CHECK(document["lower"]["lattice"] == "C1");
    CHECK(document["shard"]["top_level_boxes"] == 168);
    CHECK(result.err.find("undecided") != std::string::npos);
    const Run table = run("critical --p 2 --max-boxes 50 --shard 1/2");
    CHECK(table.status == 4);
    CHECK(table.out.find("shard 1/2") != std::string::npos);
    CHECK(table.out.find("(not proved)") != std::string::npos);
    // A shard bounds the lattice packings of its own start boxes only.
    CHECK(table.out.find("for the lattice packings in this shard's start boxes only") != std::string::npos);
    CHECK(table.out.find("for every lattice packing in this shard's start boxes (not proved)") != std::string::npos);
}

TEST_CASE("critical --merge: sums shards i/n, and refuses a shard missing, repeated, of another T or not a shard") {
    const Scratch scratch;
    const std::string dir = scratch.path + "/";
    // Two shards of 2, each stopped by its budget: the merge is undecided (exit 4) with the leaves summed.
    for (const char* shard : {"0/2", "1/2"}) {
        const std::string name = std::string("shard") + shard[0] + ".json";
        CHECK(run(std::string("critical --p 2 --gap 0.01 --max-boxes 30 --json --shard ") + shard + " > " + dir + name).status == 4);
    }
    const Run merged = run("critical --merge " + dir + "shard0.json " + dir + "shard1.json --json");
    INFO(merged.err);
    CHECK(merged.status == 4);
    const auto document = nlohmann::json::parse(merged.out);
    const auto first = nlohmann::json::parse(std::ifstream(dir + "shard0.json"));
    const auto second = nlohmann::json::parse(std::ifstream(dir + "shard1.json"));
    CHECK(document["status"] == "undecided");
    CHECK(document["processed"].get<long>() == first["processed"].get<long>() + second["processed"].get<long>());
    CHECK(document["boxes"]["undecided_budget"].get<long>() ==
          first["boxes"]["undecided_budget"].get<long>() + second["boxes"]["undecided_budget"].get<long>());
    CHECK(document["start_boxes"].get<long>() == 168);
    CHECK(document["shard"]["count"] == 1);
    CHECK(document["merged"] == true);
    CHECK_FALSE(document.contains("threads"));
    const Run table = run("critical --merge " + dir + "shard0.json " + dir + "shard1.json");
    CHECK(table.status == 4);
    CHECK(table.out.find("the shards' wall times summed") != std::string::npos);
    CHECK(document["threshold"] == first["threshold"]);
    CHECK(document["message"].get<std::string>().find("2 of 2 shards undecided") != std::string::npos);
    check_error("critical --merge " + dir + "shard0.json", 2, "shards missing of 2: 1");
    check_error("critical --merge " + dir + "shard0.json " + dir + "shard0.json", 2, "given twice");
    check_error("critical --p 2 --merge " + dir + "shard0.json", 2, "give no --p");
    check_error("critical --merge " + dir + "nothing.json", 2, "cannot open");
    check_error("critical --merge /dev/null", 2, "not a regular file");
    // Another gap gives another T: the shard does not belong to this merge.
    CHECK(run("critical --p 2 --gap 0.02 --max-boxes 30 --json --shard 1/2 > " + dir + "other.json").status == 4);
    check_error("critical --merge " + dir + "shard0.json " + dir + "other.json", 2, "another p or gap");
    // A T edited in a shard file no longer matches the T recomputed at its p and gap.
    auto edited = first;
    edited["threshold"]["lo"] = "0.1";
    std::ofstream(dir + "edited.json") << edited.dump();
    const Run other_threshold = run("critical --merge " + dir + "edited.json " + dir + "shard1.json");
    CHECK(other_threshold.status == 2);
    CHECK(other_threshold.out.empty());
    CHECK(other_threshold.err.find("has another T") != std::string::npos);
    std::ofstream(dir + "density.json") << run("density --family C0 --p 1.5 --json").out;
    check_error("critical --merge " + dir + "density.json", 2, "not a document of superpack critical");
}

TEST_CASE("critical --around R --certificate FILE: the boxes around C1's images, proved, certified and verified") {
    const Scratch scratch;
    const std::string file = scratch.path + "/critical.json";
    const Run result = run("critical --p 2 --around 1e-5 --certificate " + file + " --json");
    INFO(result.err);
    REQUIRE(result.status == 0);
    const auto document = nlohmann::json::parse(result.out);
    CHECK(document["status"] == "proved");
    CHECK(document["start_boxes"] == 4);
    CHECK_FALSE(document.contains("shard"));
    // T and V(K) / T hold on these boxes only: their names say so, and no field claims them for
    // every lattice packing.
    CHECK(document.contains("threshold_around_images"));
    CHECK(document["upper_around_images"].contains("phi"));
    CHECK_FALSE(document.contains("threshold"));
    CHECK_FALSE(document.contains("upper"));
    const Run table = run("critical --p 2 --around 1e-5");
    CHECK(table.out.find("for the lattice packings in the boxes around the images only\n") != std::string::npos);
    CHECK(table.out.find("for every lattice packing in the boxes around the images\n") != std::string::npos);
    const Run verified = run("verify " + file);
    INFO(verified.out << verified.err);
    CHECK(verified.status == 0);
    CHECK(verified.out.find("|det| >=") != std::string::npos);
    // Such a run is no shard: --merge refuses it, whatever its shard fields would say.
    CHECK(run("critical --p 2 --around 1e-5 --json > " + scratch.path + "/around.json").status == 0);
    check_error("critical --merge " + scratch.path + "/around.json", 2, "not a shard");
    check_error("critical --merge " + scratch.path + "/around.json --certificate " + scratch.path + "/merged.json", 2,
                "writes no certificate");
    // A shard document whose box count is not its shard's.
    auto edited = nlohmann::json::parse(std::ifstream(scratch.path + "/around.json"));
    edited["shard"] = {{"index", 0}, {"count", 1}, {"top_level_boxes", 168}, {"split", 0}};
    edited["threshold"] = edited["threshold_around_images"];  // a merge reads a shard's T by this name
    std::ofstream(scratch.path + "/forged.json") << edited.dump();
    check_error("critical --merge " + scratch.path + "/forged.json", 2, "has 4 start boxes, not 168");
    // --cover joins shards' certificates only: the file written above holds 4 start boxes of
    // no split domain, and a cover must be written beside its parts.
    check_error("critical --cover " + file + " --certificate " + scratch.path + "/cover.json", 2, "4 start boxes, fewer than the 168");
    check_error("verify --threads 65 " + file, 2, "--threads: 1 to 64");
    check_error("critical --cover " + file, 2, "--certificate FILE is required");
    check_error("critical --cover " + file + " --certificate /tmp/cover.json", 2, "not in the directory");
    // Every part is there, a regular file and no link, before the first is read: a missing one
    // after a file that is no certificate is the one named.
    std::ofstream(scratch.path + "/text.json") << "not JSON";
    check_error("critical --cover " + scratch.path + "/text.json " + scratch.path + "/missing.json --certificate " +
                    scratch.path + "/cover.json",
                2, "cannot open '" + scratch.path + "/missing.json'");
    std::filesystem::create_symlink(file, scratch.path + "/link.json");
    check_error("critical --cover " + scratch.path + "/link.json --certificate " + scratch.path + "/cover.json", 2,
                "is a symbolic link");
    // D14 at p = 3/5 has seven contact pairs: no closing region in the six-pair chart (after the
    // progress line of best).
    const Run seven = run("critical --p 0.6 --around 1e-5");
    CHECK(seven.status == 2);
    CHECK(seven.out.empty());
    CHECK(seven.err.find("no closing region") != std::string::npos);
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

TEST_CASE("inputs that were internal errors get the right exit and one line") {
    // Beyond the supported range of p: refused with the limit.
    check_error("check-lattice --p 1e17 --basis '2,0,0;0,2,0;0,0,2'", 2, "10^6");
    check_error("superdisk --p 1e308", 2, "10^-6 <= p <= 10^6");
    check_error("superdisk --p 1e-400", 2, "10^-6 <= p <= 10^6");
    check_error("density --family C0 --p 1000001", 2, "10^6");
    // A legal p > 1/2 whose binary64 enclosure touches 1/2: undecided at this precision, with the hint,
    // and the hint works.
    check_error("density --family O0 --p 0.5000000000000000001", 4, "try --digits 30");
    // At 30 digits phi is certified (the lattice is nearly singular there: whether it packs may stay undecided).
    const Run thirty = run("density --family O0 --p 0.5000000000000000001 --digits 30 --json");
    CHECK((thirty.status == 0 || thirty.status == 4));
    CHECK(nlohmann::json::parse(thirty.out)["status"] == "certified");
    // There the power |x|^(2p - 1) reaches 0 with a negative exponent: the derivative is
    // unbounded, Krawczyk is undecided, and the report says so (exit 4) with a hint.
    const Run disk = run("superdisk --p 0.5000000000000000001");
    CHECK(disk.status == 4);
    CHECK(lines(disk.err) == 1);
    CHECK(disk.err.find("undecided") != std::string::npos);
    CHECK(disk.err.find("try --digits 30") != std::string::npos);
    const Run disk_json = run("superdisk --p 0.5000000000000000001 --json");
    CHECK(disk_json.status == 4);
    CHECK(nlohmann::json::parse(disk_json.out)["status"] == "undecided");
    // A directory where a file or a directory should be, refused before any computation.
    const Scratch scratch;
    const std::string file = scratch.path + "/plain";
    std::ofstream(file) << "x";
    check_error("audit --family C0 --output-directory " + file, 2, "not a directory");
    check_error("audit --family C0 --output-directory " + scratch.path + "/missing", 2, "does not exist");
    CHECK(!std::filesystem::exists(scratch.path + "/missing"));
    check_error("verify " + scratch.path, 2, "unreadable");
    check_error("verify " + scratch.path + "/none.json", 2, "unreadable");
}

TEST_CASE("--json: usage errors too print exactly one JSON document") {
    check_error("density --p 2", 2, "family");
    check_error("density --family C9 --p 2", 2, "C9");
    check_error("nosuchcommand", 2, "subcommand");
    check_error("density --family C0 --p 2 --digits 0", 2, "--digits");
    // A certified impossibility prints its own document, and no second one.
    const Run impossible = run("density --family O1 --p 1 --json");
    CHECK(impossible.status == 3);
    CHECK(nlohmann::json::parse(impossible.out)["status"] == "no_lattice");
}

TEST_CASE("limits are stated and enforced, contradictions refused, undecided is exit 4") {
    check_error("density --family C0 --p 1.5 --digits 100000", 2, "from 1 to");
    check_error("best --p 0.09", 2, "below the supported p >= 1/10");
    check_error("density --family minkowski-insertion --p 0.3 --certificate out.json", 2, "no certificate kind for the family");
    check_error("best --p 1 --starts 5000", 2, "--starts: 0 to 1000");
    check_error("best --scan 0.5:1:0.1", 2, "--scan needs --csv or --plot", false);
    check_error("best --p 1 --scan 0.5:1:0.1 --csv", 2, "not both", false);
    check_error("best --scan 0.5:100:0.1 --csv", 2, "at most 200", false);
    check_error("best --scan 0.01:1:0.1 --csv", 2, "below the supported p >= 1/10", false);
    check_error("density --family C0 --p " + std::string(400, '1'), 2, "at most 100 characters");
    // (--scan prints CSV: with --json it is a contradiction, checked last.)
    check_error("superdisk --scan 1:2:0 --csv", 2, "step", false);
    check_error("superdisk --scan 1:2:1e-400 --csv", 2, "at most", false);
    check_error("superdisk --p 1 --scan 1:2:0.5 --csv", 2, "not both");
    check_error("superdisk --p 1 --csv", 2, "--csv needs --scan");
    check_error("superdisk --scan 1:2:0.5", 2, "--scan needs --csv");
    check_error("audit --family C0 --p-range 0.5:0.6", 2, "outside the domain of C0 (p >= 1)");
    check_error("audit --family O0 --p-range 0.9:1.1", 2, "outside the domain of O0");
    check_error("audit --family C0 --p-range 1:1e400", 2, "10^6");
    check_error("audit --p-range 1:2", 2, "needs one --family");
    check_error("audit --family C0 --pieces 100000", 2, "--pieces");
    check_error("audit --family C0 --depth 99", 2, "--depth");
    check_error("check-lattice --p 2 --basis '" + std::string(2000, '1') + ",0,0;0,1,0;0,0,1'", 2, "--basis");
    // A long error line is cut: the 5000-character --scan text is echoed, the line keeps 300 characters.
    check_error("superdisk --scan " + std::string(5000, '1') + " --csv", 2, "--scan wants a:b:h", false);
    const Run scan_json = run("superdisk --scan 1:2:0.5 --csv --json");
    CHECK(scan_json.status == 2);
    CHECK(nlohmann::json::parse(scan_json.out)["error"].get<std::string>().find("not --json") != std::string::npos);
    // The superdisk below 1/2: no optimum (not applicable), a certified lattice (exit 0), one
    // progress line.
    const Run concave = run("superdisk --p 0.3");
    CHECK(concave.status == 0);
    CHECK(concave.out.find("certified lattice phi [") != std::string::npos);
    CHECK(lines(concave.err) == 1);
    const Run concave_json = run("superdisk --p 0.3 --json");
    CHECK(concave_json.status == 0);
    CHECK(nlohmann::json::parse(concave_json.out)["status"] == "not_applicable");
    // Undecided answers exit 4 after printing them: a report with an undecided cell, after its
    // whole table and log.
    const Scratch scratch;
    const Run report = run("report --p-values 0.5000000000000000001,2 --output " + scratch.path + "/report.json");
    CHECK(report.status == 4);
    CHECK(report.out.find("?  (undecided)") != std::string::npos);
    CHECK(report.out.find("full enclosures") != std::string::npos);
    CHECK(std::filesystem::exists(scratch.path + "/report.json"));
    CHECK(report.err.find("report: undecided") != std::string::npos);
}

TEST_CASE("report and audit: the default out/ is created once, a named missing directory is refused") {
    const Scratch scratch;
    const Run report = run("report --p-values 2", scratch.path);
    CHECK(report.status == 0);
    CHECK(std::filesystem::is_regular_file(scratch.path + "/out/report.json"));
    const Run missing = run("report --p-values 2 --output elsewhere/report.json", scratch.path);
    CHECK(missing.status == 2);
    CHECK(missing.err.find("does not exist") != std::string::npos);
    CHECK(!std::filesystem::exists(scratch.path + "/elsewhere"));
    // A symbolic link at the log is refused, its target untouched.
    std::ofstream(scratch.path + "/victim") << "precious";
    std::filesystem::create_symlink(scratch.path + "/victim", scratch.path + "/link.json");
    const Run link = run("report --p-values 2 --output link.json", scratch.path);
    CHECK(link.status == 2);
    CHECK(link.err.find("symbolic link") != std::string::npos);
    std::ifstream victim(scratch.path + "/victim");
    CHECK(std::string(std::istreambuf_iterator<char>(victim), {}) == "precious");
}

TEST_CASE("density says whether the lattice is a packing, tables honour --digits, report aligns") {
    const Run overlapping = run("density --family O1 --p 0.6");
    CHECK(overlapping.status == 0);
    CHECK(overlapping.out.find("not a packing: phi is V/|det|, no density") != std::string::npos);
    CHECK(overlapping.out.find("witness (1, -1, -1)") != std::string::npos);
    CHECK(overlapping.out.find("  e3 ") != std::string::npos);  // the basis is printed
    const auto document = nlohmann::json::parse(run("density --family O1 --p 0.6 --json").out);
    CHECK(document["packing"]["verdict"] == "overlapping");
    CHECK(document["note"] == "not a packing: phi is V/|det|, no density");
    const Run packing = run("density --family C0 --p 1.5");
    CHECK(packing.out.find("packing     yes, 12 contacts") != std::string::npos);
    CHECK(packing.out.find("density") != std::string::npos);
    CHECK(nlohmann::json::parse(run("density --family C0 --p 1.5 --json").out)["packing"]["verdict"] == "admissible");
    // --digits 30: the table prints 30 significant digits (8.03779649631764414964990296...e-01).
    const Run thirty = run("density --family C0 --p 1.5 --digits 30");
    CHECK(thirty.out.find("[8.03779649631764414965811418597e-01, 8.03779649631764414965811418598e-01]") != std::string::npos);
    // report: every column starts at the same offset in every line, for long p too.
    const Scratch scratch;
    const Run report = run("report --p-values 1.1,23/20,0.5000000000000000001,2 --output " + scratch.path + "/r.json");
    std::istringstream table(report.out);
    std::string line;
    std::getline(table, line);  // the title
    std::getline(table, line);
    const std::size_t c1 = line.find("C1"), densest = line.find("densest");
    REQUIRE(c1 != std::string::npos);
    int rows = 0;
    while (std::getline(table, line) && line.rfind("phi enclosures", 0) != 0) {
        INFO(line);
        CHECK(line.size() > densest);
        CHECK(line[c1 - 1] == ' ');
        CHECK(line[c1] != ' ');
        CHECK(line[densest - 1] == ' ');
        CHECK(line[densest] != ' ');
        ++rows;
    }
    CHECK(rows == 4);
}

namespace {

std::vector<std::string> entries(const std::string& directory) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(directory)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

unsigned long big_endian(const unsigned char* bytes) {
    return (static_cast<unsigned long>(bytes[0]) << 24) | (static_cast<unsigned long>(bytes[1]) << 16) |
           (static_cast<unsigned long>(bytes[2]) << 8) | bytes[3];
}

// A stand-in for gnuplot in a directory of its own, to put first in PATH.
std::string fake_gnuplot(const std::string& directory, const std::string& body) {
    const std::string path = directory + "/gnuplot";
    std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
    chmod(path.c_str(), 0755);
    return "PATH=" + directory;
}

}  // namespace

TEST_CASE("best --scan --plot writes the PNG atomically and prints the table or the CSV") {
    const Scratch scratch;
    const std::string png = scratch.path + "/best.png";
    std::ofstream(png) << "an older file";
    const Run table = run("best --scan 0.6:0.7:0.05 --starts 1 --plot " + png);
    INFO(table.err);
    REQUIRE(table.status == 0);
    CHECK(table.err.find("wrote " + png + "\n") != std::string::npos);
    CHECK(lines(table.out) == 3);
    CHECK(table.out.find("0.65     phi [") != std::string::npos);
    CHECK(table.out.find("D14") != std::string::npos);
    // The signature, then the IHDR chunk: width and height big-endian.
    std::ifstream file(png, std::ios::binary);
    unsigned char head[24] = {};
    file.read(reinterpret_cast<char*>(head), sizeof head);
    REQUIRE(file.gcount() == 24);
    CHECK(std::memcmp(head, "\x89PNG\r\n\x1a\n", 8) == 0);
    CHECK(std::memcmp(head + 12, "IHDR", 4) == 0);
    CHECK(big_endian(head + 16) == 1000);
    CHECK(big_endian(head + 20) == 650);
    CHECK(entries(scratch.path) == std::vector<std::string>{"best.png"});
    // Again with --csv: the CSV on stdout, and the PNG is a new file renamed over the old one
    // (another inode), not the old one rewritten in place.
    struct stat before {}, after {};
    REQUIRE(stat(png.c_str(), &before) == 0);
    const Run csv = run("best --scan 0.6:0.65:0.05 --starts 1 --csv --plot " + png);
    REQUIRE(csv.status == 0);
    CHECK(csv.out.rfind("p,best,phi_lo,phi_hi,locally_optimal,", 0) == 0);
    CHECK(lines(csv.out) == 3);
    CHECK(csv.err.find("wrote " + png + "\n") != std::string::npos);
    REQUIRE(stat(png.c_str(), &after) == 0);
    CHECK(after.st_ino != before.st_ino);
    CHECK(entries(scratch.path) == std::vector<std::string>{"best.png"});
}

TEST_CASE("best --plot refuses bad targets and a missing or failing gnuplot before the scan and leaves no file") {
    const Scratch scratch;
    // check_error wants exactly one line on stderr: the scan's progress lines would be more.
    check_error("best --p 0.6 --plot " + scratch.path + "/best.png", 2, "--plot needs --scan", false);
    check_error("best --scan 0.6:0.7:0.05 --plot " + scratch.path, 2, "a directory", false);
    check_error("best --scan 0.6:0.7:0.05 --plot " + scratch.path + "/missing/best.png", 2, "does not exist", false);
    std::ofstream(scratch.path + "/victim") << "precious";
    std::filesystem::create_symlink(scratch.path + "/victim", scratch.path + "/link.png");
    check_error("best --scan 0.6:0.7:0.05 --plot " + scratch.path + "/link.png", 2, "symbolic link", false);
    std::ifstream victim(scratch.path + "/victim");
    CHECK(std::string(std::istreambuf_iterator<char>(victim), {}) == "precious");
    CHECK(entries(scratch.path) == std::vector<std::string>{"link.png", "victim"});

    // No gnuplot in PATH (the binary is named by its absolute path).
    const Scratch empty, output;
    const Run missing = run("best --scan 0.6:0.7:0.05 --plot best.png", output.path, "PATH=" + empty.path);
    CHECK(missing.status == 2);
    CHECK(lines(missing.err) == 1);
    CHECK(missing.err.find("gnuplot not found: install gnuplot-nox") != std::string::npos);
    CHECK(missing.out.empty());
    // A gnuplot that fails says why, in one line.
    const Scratch failing_bin;
    const Run failing = run("best --scan 0.6:0.7:0.05 --plot best.png", output.path,
                            fake_gnuplot(failing_bin.path, "echo 'gnuplot> set terminal pngcairo' >&2; echo '   line 0: no cairo' >&2; exit 3"));
    CHECK(failing.status == 2);
    CHECK(lines(failing.err) == 1);
    CHECK(failing.err.find("gnuplot failed (exit status 3): line 0: no cairo") != std::string::npos);
    CHECK(entries(output.path).empty());
}

TEST_CASE("best --plot: a gnuplot that writes no PNG leaves the old file and no temporary") {
    const Scratch bin, output;
    std::ofstream(output.path + "/best.png") << "an older file";
    // It reads its script to the end and exits 0 without writing the output.
    const Run run_result = run("best --scan 0.6:0.6:0.05 --starts 0 --plot best.png", output.path,
                               fake_gnuplot(bin.path, "while read -r line; do :; done; exit 0"));
    INFO(run_result.err);
    CHECK(run_result.status == 2);
    CHECK(run_result.err.find("gnuplot wrote no PNG for 'best.png'") != std::string::npos);
    CHECK(entries(output.path) == std::vector<std::string>{"best.png"});
    std::ifstream old(output.path + "/best.png");
    CHECK(std::string(std::istreambuf_iterator<char>(old), {}) == "an older file");
}
