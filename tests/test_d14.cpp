// The D14 family of Dostert and Vallentin (2020): against mpmath (scripts/make_d14_golden.py ->
// tests/data/d14.json) in both backends, Minkowski's lattice at p = 1/2 (= O1 there), the end
// of the branch at p*_o, the packing check with its 14 contacts, and the comparison with the
// other families on (1/2, p*_o).
#include <cstdio>
#include <filesystem>

#include "superpack/problems/families/family_lattice_check.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

// Arb at 30 digits at two of the seven p only: its root search costs 1.7 s (p = 0.52) to 4.2 s
// (p = 0.79) each, and `make test` should stay short (the others: `superpack density --digits 30`).
TEST_CASE("D14 against mpmath at seven p in (1/2, 0.79]: binary64 (all) and Arb 30 digits (two) contain it and overlap") {
    const DoubleField binary64;
    const BallField thirty{bits_for_digits(30)};
    REQUIRE(d14_golden().size() >= 7);
    for (const auto& entry : d14_golden()) {
        const std::string p_text = entry["p"];
        INFO("D14 at p = " << p_text);
        const Rational p = parse_rational(p_text);
        const auto low = enclose_family(Family::D14, p, binary64);
        REQUIRE(low.status == Outcome::proved);
        CHECK(meets(*low.phi, entry["phi"]));
        CHECK(width_upper(*low.phi) < 1e-13);
        const char* names[] = {"x", "y", "z"};
        for (int k = 0; k < 3; ++k) {
            CHECK(low.parameters[k].name == names[k]);
            CHECK(meets(low.parameters[k].value, entry[names[k]]));
        }
        // The search of [0, 9/8] x [-9/8, 9/8]^2 finds six roots (the branch, its mirror (x, z, y)
        // and four with a negative coordinate), the branch first.
        CHECK(low.branches.size() == 6);
        if (p_text != "0.52" && p_text != "0.6") continue;
        const auto high = enclose_family(Family::D14, p, thirty);
        REQUIRE(high.status == Outcome::proved);
        CHECK(meets(*high.phi, entry["phi"]));
        CHECK(overlaps(as_ball(*low.phi), *high.phi));
        CHECK(width_upper(*high.phi) < 1e-28);
        for (int k = 0; k < 3; ++k) CHECK(meets(high.parameters[k].value, entry[names[k]]));
    }
}

TEMPLATE_TEST_CASE("D14 at p = 1/2 is Minkowski's lattice: phi = 18/19, the O1 lattice reflected", "", Binary64, Arb128) {
    const TestType field;
    const auto d14 = enclose_family(Family::D14, Rational(1, 2), field);
    REQUIRE(d14.status == Outcome::proved);
    CHECK(contains(*d14.phi, field.rational(Rational(18, 19))));
    CHECK(contains(d14.parameters[0].value, field.rational(Rational(1, 3))));
    CHECK(contains(d14.parameters[1].value, field.rational(Rational(1, 6))));
    CHECK(contains(d14.parameters[2].value, field.rational(Rational(1, 2))));
    // B_O1 diag(1, 1, -1) = U B_D14 with U = [[1,1,1],[1,0,1],[1,1,0]] (det U = 1).
    const auto o1 = enclose_family(Family::O1, Rational(1, 2), field);
    REQUIRE(o1.status == Outcome::proved);
    const int U[3][3] = {{1, 1, 1}, {1, 0, 1}, {1, 1, 0}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            auto entry = field.integer(0);
            for (int k = 0; k < 3; ++k) entry = entry + field.integer(U[i][k]) * (*d14.basis)[k][j];
            const auto target = j == 2 ? -(*o1.basis)[i][j] : (*o1.basis)[i][j];
            INFO("row " << i << ", column " << j);
            CHECK(overlaps(entry, target));
        }
    const auto check = check_family_lattice(d14, field.rational(Rational(1, 2)));
    CHECK(check.verdict == Outcome::proved);
    CHECK(check.contacts() == 14);
}

TEST_CASE("D14 is a packing with exactly 14 contacts where O0 and O1 overlap") {
    const DoubleField field;
    for (const char* p_text : {"0.55", "0.7", "0.79"}) {
        INFO("p = " << p_text);
        const Rational p = parse_rational(p_text);
        const auto d14 = enclose_family(Family::D14, p, field);
        const auto check = check_family_lattice(d14, field.rational(p));
        CHECK(check.verdict == Outcome::proved);
        CHECK(check.contacts() == 14);
        for (Family other : {Family::O0, Family::O1}) {
            const auto lattice = enclose_family(other, p, field);
            REQUIRE(lattice.status == Outcome::proved);
            CHECK(check_family_lattice(lattice, field.rational(p)).verdict == Outcome::refuted);
        }
    }
}

TEST_CASE("D14 ends at p*_o: no lattice beyond it, outside the domain refused") {
    const DoubleField field;
    const auto beyond = enclose_family(Family::D14, Rational(17, 20), field);
    CHECK(beyond.status == Outcome::refuted);
    CHECK(!beyond.basis);
    CHECK(beyond.message.find("no lattice on the Dostert-Vallentin branch") != std::string::npos);
    CHECK_THROWS_AS(enclose_family(Family::D14, Rational(49, 100), field), InputError);
    CHECK_THROWS_AS(enclose_family(Family::D14, Rational(101, 100), field), InputError);
    CHECK(parse_family("D14") == Family::D14);
    CHECK(claimed_contacts(Family::D14) == 14);
}

// NOTES.md 11.10: at p*_o = ln3/ln4 (4^p = 3) the branch ends on the body-centred cubic lattice,
// which is also O0 there (c = 1/2) and where the six-pair lattice S6 of (p*_o, 1) begins.
TEMPLATE_TEST_CASE("D14 and O0 at p*_o are both the BCC lattice with seven contact pairs", "", Binary64, Arb128) {
    using I = typename TestType::Interval;
    const TestType field;
    const I p = log(field.integer(3)) / log(field.integer(4));
    const I half = field.rational(Rational(1, 2));
    for (const I& equation : d14_equations(std::vector<I>{half, half, half}, p)) CHECK(contains_zero(equation));
    CHECK(contains(octahedral_height(p), half));
    // O0's rows (2,0,0), (0,2,0), (1,1,1) = U times D14's rows (-1,1,1), (1,-1,1), (1,1,-1), det U = 1.
    const Basis<I> d14 = d14_basis(half, half, half), o0 = o0_basis(p);
    const int U[3][3] = {{0, 1, 1}, {1, 0, 1}, {1, 1, 1}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            auto entry = field.integer(0);
            for (int k = 0; k < 3; ++k) entry = entry + field.integer(U[i][k]) * d14[k][j];
            INFO("row " << i << ", column " << j);
            CHECK(overlaps(entry, o0[i][j]));
        }
    // Seven pairs of contacts: (+-1, +-1, +-1) and 2 e_i have norm exactly 2 at p*_o.
    const auto two = field.integer(2);
    CHECK(contains(pow_nonneg(field.integer(3), field.integer(1) / (two * p)), two));
}

TEST_CASE("report: D14 is the densest certified packing at p = 0.6, and no lattice at p = 0.8, where S6 is (exit 0)") {
    const std::string file = std::string(std::filesystem::temp_directory_path() / "superpack-test-d14-report.json");
    const std::string command = std::string(SUPERPACK_BINARY) + " report --p-values 0.6,0.8 --json --output " + file + " 2>/dev/null";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::string out;
    char buffer[4096];
    while (std::size_t n = fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    CHECK(WEXITSTATUS(pclose(pipe)) == 0);
    std::filesystem::remove(file);
    const nlohmann::json document = nlohmann::json::parse(out);
    CHECK(document["rows"][0]["densest"] == "D14");
    CHECK(document["rows"][0]["families"]["D14"]["packing"]["verdict"] == "admissible");
    CHECK(document["rows"][0]["families"]["D14"]["packing"]["contacts"] == 14);
    CHECK(document["rows"][1]["densest"] == "S6");  // superpack's six-pair family, denser than O0 (NOTES 4.2)
    CHECK(document["rows"][1]["families"]["D14"]["status"] == "no_lattice");
}
