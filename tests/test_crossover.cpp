#include <cmath>

#include "crossover_reference.hpp"
#include "superpack/problems/crossover/crossover.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

// The pieces cover [lo, hi] with no gap or overlap, in order.
void require_partition(const std::vector<SignPiece>& pieces, double lo, double hi) {
    REQUIRE(!pieces.empty());
    CHECK(pieces.front().p.lower() == lo);
    CHECK(pieces.back().p.upper() == hi);
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k) CHECK(pieces[k].p.upper() == pieces[k + 1].p.lower());
}

}  // namespace

TEMPLATE_TEST_CASE("crossover cubic: one zero of phi_C1 - phi_C0 in (1, 10], at the mpmath p*_c", "", Binary64,
                   Arb128) {
    const TestType field;
    const auto crossover = certify_cubic_crossover(field, 30);
    INFO(crossover.message);
    REQUIRE(crossover.certified);
    CHECK(meets(*crossover.p, reference_text("p_c")));
    CHECK(meets(*crossover.phi, reference_text("phi_c")));
    CHECK(crossover.sign_left == -1);
    CHECK(crossover.sign_right == 1);
    require_partition(crossover.pieces, 1.0, 10.0);
    std::size_t roots = 0;
    for (const SignPiece& piece : crossover.pieces) {
        CHECK(piece.claim != PieceClaim::undecided);
        if (piece.claim == PieceClaim::root) {
            ++roots;
            CHECK(piece.p.lower() < 1.1509);
            CHECK(piece.p.upper() > 1.1508);
        }
    }
    CHECK(roots == 1);
    REQUIRE(crossover.newton);
    CHECK(contains(crossover.newton->initial_box, *crossover.p));
    CHECK(certainly_positive(crossover.newton->derivative));
}

TEST_CASE("crossover cubic at 30 and 60 digits: widths, and the two precisions overlap") {
    const auto coarse = certify_cubic_crossover(BallField{bits_for_digits(30)}, 30);
    const auto fine = certify_cubic_crossover(BallField{bits_for_digits(60)}, 60);
    REQUIRE(coarse.certified);
    REQUIRE(fine.certified);
    CHECK(width_upper(*coarse.p) <= 1e-30);
    CHECK(width_upper(*coarse.phi) <= 1e-29);
    CHECK(width_upper(*fine.p) <= 1e-60);
    CHECK(overlaps(as_ball(*coarse.p), as_ball(*fine.p)));
    CHECK(overlaps(as_ball(*coarse.phi), as_ball(*fine.phi)));
    CHECK(meets(*fine.p, reference_text("p_c")));
}

TEMPLATE_TEST_CASE("at p = 1 both cubic families are FCC: s in closed form, phi = pi/sqrt18", "", Binary64, Arb128) {
    const TestType field;
    const auto one = field.integer(1);
    const auto c0 = enclose_density_slope(Family::C0, one);
    const auto c1 = enclose_density_slope(Family::C1, one);
    REQUIRE(c0.status == Outcome::proved);
    REQUIRE(c1.status == Outcome::proved);
    const auto root2 = sqrt(field.integer(2));
    CHECK(overlaps(c0.parameters[0].value, (field.integer(2) - root2) / field.integer(4)));
    CHECK(overlaps(c1.parameters[0].value, root2 / field.integer(6)));
    CHECK(meets(*c0.phi, reference_text("fcc")));
    CHECK(meets(*c1.phi, reference_text("fcc")));
    // The slopes differ at p = 1, so first order decides the sign of g just right of 1.
    CHECK(certainly_less(*c1.slope, *c0.slope));
}

TEMPLATE_TEST_CASE("family slopes by the implicit function theorem match mpmath's numerical derivative", "", Binary64,
                   Arb128) {
    const TestType field;
    for (const auto& [name, values] : crossover_reference()["slopes"].items()) {
        const Family family = parse_family(name);
        for (const auto& [p_text, value] : values.items()) {
            INFO(name << " at p = " << p_text);
            const auto slope = enclose_density_slope(family, field.rational(parse_rational(p_text)));
            REQUIRE(slope.status == Outcome::proved);
            CHECK(meets(*slope.slope, value.template get<std::string>()));
            CHECK(width_upper(*slope.slope) < 1e-12);
        }
    }
}

TEMPLATE_TEST_CASE("near p = 1 and at p = 10: g = phi_C1 - phi_C0 has the certified sign", "", Binary64, Arb128) {
    const TestType field;
    // g' < 0 on a whole piece [1, 1 + 1/8192]: with g(1) = 0 this is the left-end argument.
    const auto piece = from_doubles(field.integer(0), 1.0, 1.0 + 1.0 / 8192);
    const auto c0 = enclose_density_slope(Family::C0, piece);
    const auto c1 = enclose_density_slope(Family::C1, piece);
    REQUIRE(c0.status == Outcome::proved);
    REQUIRE(c1.status == Outcome::proved);
    CHECK(certainly_negative(*c1.slope - *c0.slope));
    for (const auto& [p_text, value] : crossover_reference()["difference"].items()) {
        INFO("p = " << p_text);
        const Rational p = parse_rational(p_text);
        const auto g = *enclose_family(Family::C1, p, field).phi - *enclose_family(Family::C0, p, field).phi;
        CHECK(meets(g, value.template get<std::string>()));
        CHECK((p < parse_rational("1.1508") ? certainly_negative(g) : certainly_positive(g)));
    }
}

TEMPLATE_TEST_CASE("crossover octahedral: the root of Eq. (6) is ln3/ln4 and O0 meets O1 there", "", Binary64,
                   Arb128) {
    const TestType field;
    const auto crossover = certify_octahedral_crossover(field, 30);
    INFO(crossover.message);
    REQUIRE(crossover.certified);
    CHECK(crossover.closed_form == Outcome::proved);
    CHECK(meets(crossover.newton->box, reference_text("eq6_root")));
    CHECK(meets(*crossover.p, reference_text("p_o")));
    CHECK(meets(*crossover.phi, reference_text("phi_o")));
    CHECK(meets(*crossover.o1_phi, reference_text("phi_o")));
    CHECK(crossover.same_lattice);
    CHECK(crossover.densities_meet == Outcome::proved);
    // |det| = 4 for both lattices at p*_o.
    CHECK(overlaps(abs(*crossover.o1_determinant), field.integer(4)));
    require_partition(crossover.pieces, 0.5, 1.0);
    for (const SignPiece& piece : crossover.pieces) CHECK(piece.claim != PieceClaim::undecided);
}

TEST_CASE("crossover octahedral at 30 and 60 digits: widths, and the two precisions overlap") {
    const auto coarse = certify_octahedral_crossover(BallField{bits_for_digits(30)}, 30);
    const auto fine = certify_octahedral_crossover(BallField{bits_for_digits(60)}, 60);
    REQUIRE(coarse.certified);
    REQUIRE(fine.certified);
    CHECK(width_upper(*coarse.p) <= 1e-30);
    CHECK(width_upper(*coarse.phi) <= 1e-29);
    CHECK(width_upper(fine.newton->box) <= 1e-60);
    CHECK(overlaps(*coarse.phi, *fine.phi));
}

TEST_CASE("printed decimals are read as truncated and as rounded") {
    const BallField field{128};
    const Ball p_c = field.rational(parse_rational("1.15087695"));
    // The paper's 1.1509... is p*_c rounded, not truncated.
    const auto check = check_printed(p_c, "1.1509");
    CHECK(check.truncated == Outcome::refuted);
    CHECK(check.rounded == Outcome::proved);
    const auto negative = check_printed(field.rational(parse_rational("-0.029412")), "-0.02941");
    CHECK(negative.truncated == Outcome::proved);
    CHECK(check_printed(field.rational(parse_rational("-0.029408")), "-0.02941").truncated == Outcome::refuted);
    // An enclosure straddling an end of the reading is undecided, not rounded to a verdict.
    const Ball straddle = hull(field.rational(parse_rational("1.15089")), field.rational(parse_rational("1.15091")));
    CHECK(check_printed(straddle, "1.1509").truncated == Outcome::undecided);
}

TEST_CASE("crossover and slopes on the command line: one JSON document, exit codes") {
    auto run = [](const std::string& arguments, int& status) {
        const std::string command = std::string(SUPERPACK_BINARY) + " " + arguments + " 2>/dev/null";
        FILE* pipe = popen(command.c_str(), "r");
        REQUIRE(pipe != nullptr);
        std::string out;
        char buffer[4096];
        while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
        const int raw = pclose(pipe);
        status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
        return out;
    };
    int status = -1;
    const auto cubic = nlohmann::json::parse(run("crossover cubic --digits 30 --json", status));
    CHECK(status == 0);
    CHECK(cubic["certified"] == true);
    CHECK(cubic["unique_on"] == nlohmann::json::array({"1", "10"}));
    CHECK(cubic["sign_left"] == "negative");
    CHECK(cubic["sign_right"] == "positive");
    CHECK(cubic["p"]["lo"].get<std::string>().rfind("1.150876953749930385621729966859", 0) == 0);
    CHECK(cubic["pieces"]["undecided"] == 0);
    CHECK(cubic["pieces"]["root"] == 1);
    const auto octahedral = nlohmann::json::parse(run("crossover octahedral --json", status));
    CHECK(status == 0);
    CHECK(octahedral["densities_meet"] == "agree");
    const auto slopes = nlohmann::json::parse(run("slopes --json", status));
    CHECK(status == 0);
    CHECK(slopes["a_plus_family"] == "C0");
    CHECK(slopes["paper"]["a_plus"]["certified_vs_printed"]["as_truncated"] == "disagree");
    run("crossover sideways", status);
    CHECK(status == 2);
}
