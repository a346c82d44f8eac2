// Superdisks: the two lattices and the certified optimum against independent mpmath values
// (scripts/make_superdisk_golden.py -> tests/data/superdisk.json), both backends, identities.
#include <cstdio>

#include "support.hpp"
#include "superpack/problems/superdisk/superdisk.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

const nlohmann::json& superdisk_golden() {
    static const nlohmann::json data = [] {
        std::ifstream file(std::string(SUPERPACK_TEST_DATA) + "/superdisk.json");
        REQUIRE(file.good());
        return nlohmann::json::parse(file);
    }();
    return data;
}

template <class I>
void check_partition(const SuperdiskReport<I>& report) {
    // The pieces, sorted by t, must tile [0, 1] with no gap and no undecided piece.
    REQUIRE(!report.pieces.empty());
    CHECK(contains(report.pieces.front().t, field_of(report.area).integer(0)));
    CHECK(contains(report.pieces.back().t, field_of(report.area).integer(1)));
    // (a ball backend rounds the split points outward, so neighbours may overlap slightly).
    auto covered = report.pieces.front().t;
    for (std::size_t k = 0; k < report.pieces.size(); ++k) {
        CHECK(report.pieces[k].verdict != PieceVerdict::undecided);
        CHECK_FALSE(certainly_less(upper_point(covered), lower_point(report.pieces[k].t)));
        covered = hull(covered, report.pieces[k].t);
    }
}

}  // namespace

TEMPLATE_TEST_CASE("superdisk lattices meet the mpmath values", "[superdisk]", Binary64, Arb128) {
    const TestType field;
    for (const auto& [p, values] : superdisk_golden().items()) {
        INFO("p = " << p);
        const Rational exact = parse_rational(p);
        const auto lambda0 = enclose_hexagon_lattice(Rational(1), exact, field);
        const auto lambda1 = enclose_hexagon_lattice(Rational(0), exact, field);
        REQUIRE(lambda0.status == RootStatus::unique);
        REQUIRE(lambda1.status == RootStatus::unique);
        CHECK(meets(lambda0.phi, std::string(values["phi_Lambda0"])));
        CHECK(meets(lambda1.phi, std::string(values["phi_Lambda1"])));
        CHECK(width_upper(lambda0.phi) < width_budget(field));
        CHECK(width_upper(lambda1.phi) < width_budget(field));
        CHECK(meets(enclose_ball_volume(field.rational(exact), 2), std::string(values["area"])));
    }
}

TEST_CASE("superdisk lattices: binary64 and Arb enclosures overlap", "[superdisk]") {
    for (const char* p : {"0.6", "1.5", "3"}) {
        const auto a = enclose_hexagon_lattice(Rational(1), parse_rational(p), Binary64{});
        const auto b = enclose_hexagon_lattice(Rational(1), parse_rational(p), Arb400{});
        CHECK(overlaps(as_ball(a.phi), b.phi));
        CHECK(width_upper(b.phi) < width_budget(Arb400{}));
    }
}

TEST_CASE("superdisk optimum: width 1e-9, the mpmath minimum, the attaining family", "[superdisk]") {
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"0.6", "Lambda0"}, {"0.75", "Lambda0"}, {"1.1", "Lambda1"}, {"1.25", "Lambda1"},
        {"1.5", "Lambda0"}, {"2", "Lambda0"},    {"3", "Lambda0"}};
    for (const auto& [p, family] : expected) {
        INFO("p = " << p);
        const auto report = analyse_superdisk(parse_rational(p), DoubleField{});
        REQUIRE(report.status == OptimumStatus::certified);
        CHECK(width_upper(report.optimal_phi) <= 1e-9);
        CHECK(meets(report.optimal_phi, superdisk_golden()[p]["optimal_phi"].get<std::string>()));
        CHECK(report.attained_by == family);
        // The other family is certified worse: its gap excludes 0.
        const auto& other_gap = family == "Lambda0" ? report.gap_lambda1 : report.gap_lambda0;
        CHECK(certainly_positive(other_gap));
        check_partition(report);
    }
}

TEST_CASE("superdisk optimum with Arb overlaps the binary64 one", "[superdisk]") {
    const auto fast = analyse_superdisk(parse_rational("1.1"), DoubleField{});
    const auto ball = analyse_superdisk(parse_rational("1.1"), Arb128{});
    REQUIRE(ball.status == OptimumStatus::certified);
    CHECK(overlaps(as_ball(fast.optimal_phi), ball.optimal_phi));
    CHECK(ball.attained_by == "Lambda1");
    check_partition(ball);
}

TEST_CASE("superdisk identities: the disk, the square, the concave case", "[superdisk]") {
    // p = 1: every u gives the hexagonal lattice, phi = pi / (2 sqrt 3).
    const auto disk = analyse_superdisk(Rational(1), DoubleField{});
    REQUIRE(disk.status == OptimumStatus::certified);
    CHECK(meets(disk.optimal_phi, superdisk_golden()["1"]["optimal_phi"].get<std::string>()));
    const DInterval exact = DoubleField{}.pi() / (DoubleField{}.integer(2) * sqrt(DoubleField{}.integer(3)));
    CHECK(overlaps(disk.optimal_phi, exact));
    CHECK(overlaps(disk.lambda0.phi, exact));
    CHECK(overlaps(disk.lambda1.phi, exact));
    CHECK(disk.attained_by == "Lambda0 and Lambda1");
    // p = 1/2: the square |x| + |y| <= 1 tiles; Lambda1 (u = (1, 0), v = (1/2, 1/2)) is a tiling.
    const auto square = analyse_superdisk(Rational(1, 2), Arb128{});
    REQUIRE(square.status == OptimumStatus::certified);
    CHECK(meets(square.optimal_phi, "1"));
    CHECK(meets(square.lambda1.phi, "1"));
    CHECK(meets(square.area, "2"));
    CHECK(square.attained_by == "Lambda1");
    CHECK(contains_zero(square.gap_lambda1));
    // p < 1/2: concave, no optimum claimed.
    const auto star = analyse_superdisk(parse_rational("0.3"), DoubleField{});
    CHECK(star.status == OptimumStatus::not_applicable);
    CHECK(star.pieces.empty());
}

TEST_CASE("superdisk CLI: one JSON document with the contract's names; concave p has no optimum", "[superdisk]") {
    auto run = [](const std::string& arguments, int& status) {
        const std::string command = std::string(SUPERPACK_BINARY) + " " + arguments + " 2>/dev/null";
        std::string out;
        FILE* pipe = popen(command.c_str(), "r");
        REQUIRE(pipe != nullptr);
        char buffer[4096];
        while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
        const int code = pclose(pipe);
        status = WIFEXITED(code) ? WEXITSTATUS(code) : -1;
        return out;
    };
    int status = -1;
    const auto document = nlohmann::json::parse(run("superdisk --p 2 --json", status));
    CHECK(status == 0);
    for (const char* key : {"area", "lattices", "optimal_phi", "optimal_lattice", "attained_by", "gap", "proof"})
        CHECK(document.contains(key));
    CHECK(document["lattices"]["Lambda0"].contains("phi"));
    CHECK(document["lattices"]["Lambda1"].contains("phi"));
    CHECK(document["attained_by"] == "Lambda0");
    CHECK(meets(from_doubles(DInterval(0), std::stod(std::string(document["optimal_phi"]["lo"])),
                             std::stod(std::string(document["optimal_phi"]["hi"]))),
                std::string(superdisk_golden()["2"]["optimal_phi"])));
    CHECK(!document["proof"]["pieces"].empty());
    const auto concave = nlohmann::json::parse(run("superdisk --p 0.3 --json", status));
    CHECK(status == 0);  // no optimum and no Lambda lattices; the concave lattice is certified (test_star_disk)
    CHECK_FALSE(concave.contains("optimal_phi"));
    CHECK(concave["status"] == "not_applicable");
    CHECK(concave["concave_lattice"]["status"] == "certified");
    run("superdisk --scan 1:2:0.5", status);
    CHECK(status == 2);
    const std::string csv = run("superdisk --scan 1:1.5:0.5 --csv", status);
    CHECK(status == 0);
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 3);
}
