// The audit driver on short ranges with known answers (the full ranges run in bench/bench_audit).
#include "superpack/problems/families/audit.hpp"
#include "support.hpp"

using namespace superpack;
using namespace superpack::test;

namespace {

// The pieces cover [lo, hi] in order, without gaps or overlaps.
void check_cover(const AuditResult& result) {
    REQUIRE(!result.pieces.empty());
    CHECK(result.pieces.front().lo == result.range.lo);
    CHECK(result.pieces.back().hi == result.range.hi);
    for (std::size_t k = 1; k < result.pieces.size(); ++k) CHECK(result.pieces[k - 1].hi == result.pieces[k].lo);
}

}  // namespace

TEST_CASE("C0 and C1 on [2, 2.5]: packings with 12 contacts on every piece") {
    for (Family family : {Family::C0, Family::C1}) {
        const AuditResult result = audit_family(family, {Rational(2), Rational(5, 2), {}, "test"}, {4, 4});
        check_cover(result);
        for (const AuditPiece& piece : result.pieces) {
            CHECK(piece.outcome == "packing");
            CHECK(piece.contacts == 12);
        }
    }
}

TEST_CASE("O0 around p*_o: overlap below with witness +-(1,1,-2), packing above, undecided only at p*_o") {
    const AuditRange range = claimed_audit_range(Family::O0);
    const AuditResult result = audit_family(Family::O0, {Rational(3, 4), Rational(81, 100), range.breaks, "test"}, {4, 40});
    check_cover(result);
    const DoubleField field;
    const DInterval crossover = log(field.integer(3)) / log(field.integer(4));
    for (const AuditPiece& piece : result.pieces) {
        const DInterval p = hull(field.rational(piece.lo), field.rational(piece.hi));
        if (certainly_less(p, crossover)) {
            CHECK(piece.outcome == "overlapping");
            REQUIRE(piece.witness);
            CHECK(std::abs((*piece.witness)[2]) == 2);
        } else if (certainly_less(crossover, p)) {
            CHECK(piece.outcome == "packing");
            CHECK(piece.contacts == 12);
        } else {
            // The piece holding p*_o cannot be a packing everywhere: undecided, or refuted at a
            // certified point below p*_o.
            CHECK((piece.outcome == "undecided" || piece.outcome == "overlapping_at_point"));
            CHECK(width_upper(p) < 1e-8);
        }
    }
}

TEST_CASE("O1 on [0.6, 0.603]: the published lattice overlaps on every piece (erratum)") {
    const AuditResult result = audit_family(Family::O1, {parse_rational("0.6"), parse_rational("0.603"), {}, "test"}, {3, 0});
    check_cover(result);
    for (const AuditPiece& piece : result.pieces) {
        CHECK(piece.outcome == "overlapping");
        CHECK(piece.witness == Coefficients{1, -1, -1});
    }
}

TEST_CASE("O1 second root of Eq. (12) at p in [0.9, 0.901]: exists past p*_o, and overlaps") {
    const AuditResult result = audit_family(Family::O1, {parse_rational("0.9"), parse_rational("0.901"), {}, "test"}, {1, 0},
                                            AuditBranch::o1_second_root);
    REQUIRE(result.pieces.size() == 1);
    CHECK(result.pieces[0].outcome == "overlapping");
    // The complete root search at p = 0.9 agrees: exactly one root with q >= 0 (the paper says none).
    const auto lattice = enclose_family(Family::O1, parse_rational("0.9"), DoubleField{});
    CHECK(lattice.status == Outcome::refuted);
    CHECK(lattice.branches.size() == 1);
}

TEST_CASE("merged verdict ranges keep every piece") {
    const AuditResult result = audit_family(Family::C0, {Rational(3), Rational(4), {}, "test"}, {3, 2});
    const auto merged = merge_verdict_ranges(result.pieces);
    REQUIRE(merged.size() == 1);
    CHECK(merged[0].lo == Rational(3));
    CHECK(merged[0].hi == Rational(4));
}

TEST_CASE("the audit's piece limit: no bisection beyond max_pieces, the rest undecided and named") {
    // On a piece holding p*_o, O0 stays undecided at every depth: only the limit stops the bisection.
    AuditSettings settings{1, 30};
    settings.max_pieces = 5;
    const AuditRange range{parse_rational("0.7924812"), parse_rational("0.7924813"), {}, "test"};
    const AuditResult result = audit_family(Family::O0, range, settings);
    check_cover(result);
    CHECK(result.pieces.size() == 5);
    std::size_t limited = 0;
    for (const AuditPiece& piece : result.pieces) limited += piece.reason.find("piece limit 5 reached") != std::string::npos;
    CHECK(limited > 0);
    settings.initial_pieces = 6;
    CHECK_THROWS_AS(audit_family(Family::O0, range, settings), InputError);
}
