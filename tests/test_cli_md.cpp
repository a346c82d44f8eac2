// `superpack md` as a user runs it: its limits, its one JSON document (dynamics estimates and
// the certified phi of the jammed end state), the certificate it writes and the seed. Short runs
// of spheres (p = 1) and superballs at fast growth, about a second each.
#include <algorithm>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "scratch.hpp"

namespace {

using superpack::test::Run;
using superpack::test::run;
using superpack::test::Scratch;

nlohmann::json certified_document(const Run& result) {
    INFO(result.err);
    REQUIRE(result.status == 0);
    const nlohmann::json document = nlohmann::json::parse(result.out, nullptr, false);
    REQUIRE(document.is_object());
    REQUIRE(document.value("certified", false));
    return document;
}

double lower(const nlohmann::json& enclosure) { return std::stod(enclosure.at("lo").get<std::string>()); }
double upper(const nlohmann::json& enclosure) { return std::stod(enclosure.at("hi").get<std::string>()); }

}  // namespace

TEST_CASE("md: bad usage is one line on stderr and exit 2, before any computation") {
    Scratch empty;
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--p 0.4", "below 1/2"},
        {"--p 1 --n 1", "--n: 2 to 256"},
        {"--p 1 --n 257", "--n: 2 to 256"},
        {"--p 1 --growth 0", "--growth: 1e-7 to 1"},
        {"--p 1 --growth 2", "--growth: 1e-7 to 1"},
        {"--p 1 --max-collisions 0", "--max-collisions: 1 to 10^9"},
        {"--p 1 --pressure-limit 1", "--pressure-limit: 10 to 10^9"},
        {"--p 1 --cell sliding", "--cell: fixed or deforming"},
        {"--p 1 --init C9", "unknown family 'C9'"},
        {"--p 1 --certificate " + empty.path + "/missing/md.json", "does not exist"},
    };
    superpack::test::check_refused_before_work("md", cases);
}

TEST_CASE("md --json: jammed spheres, certified, denser than random loose packing and below FCC") {
    const nlohmann::json document = certified_document(run("md --p 1 --n 32 --growth 0.1 --json"));
    const nlohmann::json& dynamics = document.at("dynamics");
    CHECK(dynamics.at("jammed").get<bool>());
    CHECK(dynamics.at("reduced_pressure").get<double>() > 1e6);
    // Fast growth jams 32 spheres well below FCC's pi / sqrt 18 = 0.7405 and above 0.5.
    CHECK(lower(document.at("phi")) > 0.5);
    CHECK(upper(document.at("phi")) < 0.7405);
    CHECK(lower(document.at("phi")) <= dynamics.at("phi_estimate").get<double>() * (1 + 1e-9));
    CHECK(document.at("best_lattice").at("name") == "C0");
    CHECK(document.at("configuration").at("particles").size() == 32);
}

TEST_CASE("md: a superball run writes a certificate the checker accepts, and the seed fixes the run") {
    Scratch scratch;
    const std::string certificate = scratch.path + "/md.json";
    const std::string command = "md --p 1.5 --n 8 --growth 0.1 --json --seed 3";
    const nlohmann::json first = certified_document(run(command + " --certificate " + certificate));
    const Run verified = run("verify " + certificate);
    INFO(verified.out << verified.err);
    CHECK(verified.status == 0);
    CHECK(verified.out.find("is a packing") != std::string::npos);
    // The certificate names the command that wrote it (it said "simulate" before).
    std::ifstream file(certificate);
    CHECK(nlohmann::json::parse(file, nullptr, false).value("command", "") == "md");
    const nlohmann::json second = certified_document(run(command));
    CHECK(first.at("phi") == second.at("phi"));
    CHECK(first.at("configuration") == second.at("configuration"));
    const nlohmann::json other = certified_document(run("md --p 1.5 --n 8 --growth 0.1 --json --seed 4"));
    CHECK(other.at("configuration") != first.at("configuration"));
}

TEST_CASE("md at p = 1/2: the octahedra's face contacts stall the dynamics, which says so instead of calling it jammed") {
    const nlohmann::json document = certified_document(run("md --p 1/2 --n 32 --growth 0.1 --json"));
    const nlohmann::json& dynamics = document.at("dynamics");
    CHECK_FALSE(dynamics.at("jammed").get<bool>());
    CHECK(dynamics.at("stopped_by").get<std::string>().find("stalled") == 0);
    CHECK(upper(document.at("phi")) < 0.5);  // far from any jammed density: a loose, proved packing
}
