#include "superpack/problems/families/audit.hpp"

#include <algorithm>
#include <sstream>

#include "superpack/problems/families/family_registry.hpp"
#include "superpack/problems/families/s6_definition.hpp"
#include "superpack/problems/families/s6_branch.hpp"
#include "superpack/solve/branch_and_bound.hpp"

namespace superpack {

namespace {

DInterval piece_interval(const Rational& lo, const Rational& hi) {
    const DoubleField field;
    return hull(field.rational(lo), field.rational(hi));
}

Json parameters_json(const FamilyLattice<DInterval>& lattice) {
    Json result = Json::object();
    for (const auto& parameter : lattice.parameters) result[parameter.name] = enclosure_json(parameter.value);
    return result;
}

Json basis_json(const Basis<DInterval>& basis) {
    Json rows = Json::array();
    for (const auto& row : basis) {
        Json entries = Json::array();
        for (const auto& x : row) entries.push_back(enclosure_json(x));
        rows.push_back(entries);
    }
    return rows;
}

// O1 and D14 by continuation: the root of the contact equations is followed from p = 1/2 (O1:
// Minkowski (q, s) = (1/6, 2/3), or the second root (5/12, 1/6); D14: (x, y, z) = (1/3, 1/6, 1/2))
// piece by piece; on each piece Krawczyk proves that a box around the previous root holds exactly
// one root for every p of the piece. This avoids the full root search of enclose_family_at, whose
// cost explodes on some pieces (NOTES.md 5.5).
struct BranchTracker {
    std::vector<double> root;
    // D14: the box of the previous piece, whose root at the shared end the next box must hold
    // (the link the checker requires; near p*_o a wider box could catch the mirror root).
    std::optional<std::vector<DInterval>> previous;
    // S6: the branch from the point proof at p = 9/10, and the direction of the walk (down: each
    // piece is linked at its upper end).
    std::optional<S6Branch> s6;
    bool downward = false;
};

template <class F>
std::optional<KrawczykResult<DInterval>> follow_root(const F& equations, const std::vector<double>& root, const DInterval& p,
                                                     bool first_nonnegative) {
    const DoubleField field;
    const double radius = 2 * width_upper(p) + 1e-9;
    for (double r = radius; r < 0.05; r *= 4) {
        std::vector<DInterval> box;
        for (std::size_t k = 0; k < root.size(); ++k)
            box.push_back(from_doubles(field.integer(0), k == 0 && first_nonnegative ? std::max(0.0, root[k] - r) : root[k] - r,
                                       root[k] + r));
        KrawczykResult<DInterval> proof = krawczyk_isolate(equations, box, 0.0, 60);
        bool inside = proof.status == RootStatus::unique;
        for (std::size_t k = 0; inside && k < box.size(); ++k) inside = contains(proof.initial_box[k], proof.box[k]);
        if (inside) return proof;
    }
    return std::nullopt;
}

// D14: does the new box hold, at the piece's lower end p0, the root that the previous box holds?
bool linked_to_previous(const BranchTracker& tracker, const std::vector<DInterval>& box, const Rational& p0) {
    if (!tracker.previous) return true;
    const DInterval at = DoubleField{}.rational(p0);
    return unique_root_within([&](const auto& x) { return d14_equations(x, at); }, box, *tracker.previous);
}

// S6: the mean-value Krawczyk box of the piece, linked to the box before it (s6_branch.hpp).
FamilyLattice<DInterval> track_s6(BranchTracker& tracker, const Rational& lo, const Rational& hi) {
    FamilyLattice<DInterval> lattice{Family::S6};
    const S6Piece piece = s6_piece(*tracker.s6, lo, hi, tracker.downward ? hi : lo);
    if (piece.status != RootStatus::unique) {
        lattice.message = piece.reason;
        return lattice;
    }
    lattice.search.push_back({piece.box, RootStatus::unique, piece.root, piece.reason});
    for (int k = 0; k < 9; ++k)
        lattice.parameters.push_back({"b" + std::to_string(k / 3) + std::to_string(k % 3), piece.root[static_cast<std::size_t>(k)]});
    for (std::size_t i = 9; i < piece.root.size(); ++i) lattice.parameters.push_back({"mu" + std::to_string(i - 8), piece.root[i]});
    lattice.branches.push_back({lattice.parameters, lattice.search.back()});
    const std::vector<DInterval>& x = piece.root;
    lattice.basis = Basis<DInterval>{{{x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}}};
    lattice.status = Outcome::proved;
    lattice.message = "KKT point followed from the point proof at p = 9/10; Krawczyk (mean-value form in p): unique in the "
                      "box for every p of the piece; midpoint p0 = " + rational_text(piece.p0);
    return lattice;
}

FamilyLattice<DInterval> track_branch(Family family, BranchTracker& tracker, const DInterval& p, const Rational& lo,
                                      const Rational& hi) {
    if (family == Family::S6) return track_s6(tracker, lo, hi);
    FamilyLattice<DInterval> lattice{family};
    const bool o1 = family == Family::O1;
    const std::string equations_name = o1 ? "Eq. (12)" : "the D14 equations";
    std::optional<KrawczykResult<DInterval>> proof;
    if (o1) proof = follow_root([&](const auto& x) { return o1_equations(x, p); }, tracker.root, p, true);
    else proof = follow_root([&](const auto& x) { return d14_equations(x, p); }, tracker.root, p, false);
    if (proof && !o1 && !linked_to_previous(tracker, proof->initial_box, lo)) {
        lattice.message = "the box of the D14 equations on this piece does not hold the root of the previous piece";
        return lattice;
    }
    if (!proof) {
        lattice.message = "Krawczyk could not follow the root of " + equations_name + " onto this piece";
        return lattice;
    }
    const std::vector<DInterval>& root = proof->box;
    tracker.root.clear();
    for (const DInterval& x : root) tracker.root.push_back(mid_double(x));
    if (!o1) tracker.previous = proof->initial_box;
    lattice.search.push_back({proof->initial_box, RootStatus::unique, root, proof->reason});
    if (o1) {
        lattice.parameters = {{"l", o1_l(p)}, {"q", root[0]}, {"s", root[1]}};
        lattice.branches.push_back({{{"q", root[0]}, {"s", root[1]}}, lattice.search.back()});
        lattice.basis = o1_basis(root[0], root[1], p);
    } else {
        lattice.parameters = {{"x", root[0]}, {"y", root[1]}, {"z", root[2]}};
        lattice.branches.push_back({lattice.parameters, lattice.search.back()});
        lattice.basis = d14_basis(root[0], root[1], root[2]);
    }
    lattice.status = Outcome::proved;
    lattice.message = "root of " + equations_name + " followed by continuation from p = 1/2; Krawczyk: unique in the box";
    return lattice;
}

// One piece, without subdivision.
AuditPiece audit_piece(Family family, const Rational& lo, const Rational& hi,
                       BranchTracker* tracker = nullptr) {
    AuditPiece piece;
    piece.lo = lo;
    piece.hi = hi;
    const DInterval p = piece_interval(lo, hi);
    const FamilyLattice<DInterval> lattice = tracker != nullptr ? track_branch(family, *tracker, p, lo, hi) : enclose_family_at(family, p);
    piece.detail["p"] = Json{{"lo", rational_text(lo)}, {"hi", rational_text(hi)}};
    piece.detail["family_status"] = lattice.status == Outcome::proved ? "certified"
                                    : lattice.status == Outcome::refuted ? "no_lattice"
                                                                                 : "undecided";
    if (!lattice.message.empty()) piece.detail["family_message"] = lattice.message;
    const std::optional<Basis<DInterval>> basis = lattice.basis;
    const Json parameters = parameters_json(lattice);
    piece.detail["parameters"] = parameters;
    if (!basis) {
        piece.outcome = lattice.status == Outcome::refuted ? "no_lattice" : "undecided";
        piece.reason = "family not certified: " + lattice.message;
        return piece;
    }
    piece.lattice = std::make_shared<const FamilyLattice<DInterval>>(lattice);
    piece.detail["basis"] = basis_json(*basis);
    const std::vector<Coefficients> identities = family_contact_triples(family);
    Json identity_json = Json::array();
    for (const auto& c : identities) identity_json.push_back(coefficients_json(c));
    piece.detail["contact_identities"] = identity_json;
    const LatticeCheck<DInterval> check = check_lattice(*basis, p, [&](const Coefficients& c) {
        return std::find(identities.begin(), identities.end(), c) != identities.end();
    });
    piece.detail["check"] = lattice_check_json(check, true);
    piece.check = std::make_shared<const LatticeCheck<DInterval>>(check);
    piece.verdict = check.verdict;
    piece.contacts = check.contacts();
    piece.reason = check.reason;
    if (check.witness) piece.witness = check.witness->coefficients;
    switch (check.verdict) {
        case Outcome::proved: piece.outcome = "packing"; break;
        case Outcome::refuted: piece.outcome = "overlapping"; break;
        case Outcome::undecided: piece.outcome = "undecided"; break;
    }
    return piece;
}

// A piece of p to audit. `downward` is set when it is split: S6 below 9/10 walks down, the upper
// half first, linked to the box before.
struct AuditSpan {
    Rational lo, hi;
    int depth = 0;
    bool downward = false;
};

// audit's driver of the branch and bound, depth first in one thread, so that each piece is
// audited right after its neighbour (the continuation links them): audit_piece decides a piece;
// an unsettled one is bisected while the depth and the piece limit allow, and one that stays
// unsettled still gets the certified check at its midpoint.
struct AuditDriver {
    using Box = AuditSpan;
    using Leaf = AuditPiece;
    static constexpr bool single_reason = true;
    Family family;
    AuditBranch branch;
    const AuditSettings& settings;
    const AuditProgress& progress;
    AuditResult& result;
    std::optional<BranchTracker>& tracker;
    std::size_t& planned;  // pieces audited or still to be audited: a bisection adds one
    // D14 and S6: once a piece at the subdivision floor breaks the continuation, a later root
    // box is no longer tied to the branch (near p*_o it may hold the mirror root), so later
    // pieces are not audited: they would certify nothing about the branch, and their bisection
    // would grow full trees of 2^max_depth undecided pieces. (O1 keeps going: its point
    // refutations need no chain.)
    bool chain_broken = false;

    Examined<Box, Leaf> examine(const Box& span, Visit&) {
        if (chain_broken) return leaf_of<Box>(not_audited(span));
        AuditPiece piece = audit_piece(family, span.lo, span.hi, tracker ? &*tracker : nullptr);
        piece.detail["lattice"] = branch == AuditBranch::published ? "published" : "second root of Eq. (12)";
        const bool settled = piece.outcome == "packing" || piece.outcome == "overlapping" || piece.outcome == "no_lattice";
        if (settled) return leaf_of<Box>(std::move(piece));
        const bool budget = planned < settings.max_pieces;
        if (span.depth < settings.max_depth && budget) {
            ++planned;
            return split_of<Box, Leaf>(AuditSpan{span.lo, span.hi, span.depth, tracker && tracker->downward});
        }
        chain_broken = family == Family::D14 || family == Family::S6;
        piece.reason += budget ? " (subdivision floor reached)" : " (piece limit " + std::to_string(settings.max_pieces) + " reached)";
        // Not for S6, whose lattice is a packing wherever its point exists.
        if (family != Family::S6) check_midpoint(piece);
        return leaf_of<Box>(std::move(piece));
    }
    std::array<Box, 2> split(const Box& span) const {
        Rational middle = (span.lo + span.hi) / 2;
        middle.canonicalize();
        const AuditSpan lower{span.lo, middle, span.depth + 1}, upper{middle, span.hi, span.depth + 1};
        return span.downward ? std::array<Box, 2>{upper, lower} : std::array<Box, 2>{lower, upper};
    }
    void collect(Leaf&& piece) {
        if (progress)
            progress(std::string(to_string(family)) + " p in [" + decimal_or_fraction_text(piece.lo) + ", " +
                     decimal_or_fraction_text(piece.hi) + "]: " + piece.outcome);
        result.pieces.push_back(std::move(piece));
    }

    AuditPiece not_audited(const Box& span) const {
        AuditPiece piece;
        piece.lo = span.lo;
        piece.hi = span.hi;
        piece.reason = std::string("not audited: the continuation of the branch from ") +
                       (family == Family::S6 ? "p = 9/10" : "p = 1/2") + " broke before this piece";
        piece.detail["p"] = Json{{"lo", rational_text(span.lo)}, {"hi", rational_text(span.hi)}};
        piece.detail["family_status"] = "undecided";
        return piece;
    }
    // A refutation at one exact p of the piece is still certified: try the midpoint.
    void check_midpoint(AuditPiece& piece) const {
        Rational middle = (piece.lo + piece.hi) / 2;
        middle.canonicalize();
        BranchTracker copy = tracker ? *tracker : BranchTracker{};
        copy.previous.reset();  // the midpoint is no end of the previous piece
        const AuditPiece point = audit_piece(family, middle, middle, tracker ? &copy : nullptr);
        piece.detail["midpoint_check"] = point.detail;
        if (point.outcome == "overlapping") {
            piece.outcome = "overlapping_at_point";
            piece.witness = point.witness;
            piece.reason += "; at p = " + rational_text(middle) + " the lattice overlaps (witness in midpoint_check)";
        }
    }
};

}  // namespace

AuditRange claimed_audit_range(Family family) {
    const FamilyDefinition& definition = family_definition(family);
    if (!definition.audit_range) throw InputError(definition.not_audited);
    return definition.audit_range();
}

AuditSettings default_audit_settings(Family family) { return family_definition(family).audit_settings; }

namespace {

// The audit's input contract, checked before any piece (S6's range: sound but stricter than
// p*_o < p < 1, the rational ends are compared exactly).
void require_audit_input(Family family, const AuditRange& range, AuditBranch branch) {
    if (branch == AuditBranch::o1_second_root && family != Family::O1)
        throw InputError("the second root branch exists for O1 only");
    if (!(range.lo < range.hi)) throw InputError("empty p range");
    if (family == Family::S6) {
        const Rational anchor = s6_seed_p();
        if (range.lo < octahedral_crossover_above() || !(range.hi < Rational(1)))
            throw InputError("an S6 audit range must lie in [792482/10^6, 1) (S6 is defined on (p*_o, 1))");
        if (range.lo > anchor || range.hi < anchor)
            throw InputError("an S6 audit range must hold p = 9/10, where the branch is anchored by its point proof");
    }
}

// The ends of the segments cut into pieces: the range's, its breaks and (S6) the anchor 9/10.
std::vector<Rational> segment_ends(Family family, const AuditRange& range) {
    const Rational anchor = s6_seed_p();
    std::vector<Rational> ends{range.lo};
    if (family == Family::S6 && range.lo < anchor && anchor < range.hi) ends.push_back(anchor);
    for (const Rational& b : range.breaks)
        if (b > range.lo && b < range.hi) ends.push_back(b);
    ends.push_back(range.hi);
    std::sort(ends.begin(), ends.end());
    return ends;
}

// Where the continuation of a family's root starts: the registry's start (O1's second root at
// (q, s) = (5/12, 1/6)), or the complete root search at the exact left end when the range does
// not start at 1/2 (D14: its branch root comes first), or S6's point proof at 9/10 (kept in the
// result as its anchor). Nothing for the families whose pieces need no continuation.
std::optional<BranchTracker> continuation(Family family, const AuditRange& range, AuditBranch branch, AuditResult& result) {
    std::optional<BranchTracker> tracker;
    const FamilyDefinition& definition = family_definition(family);
    if (!definition.continuation_start.empty()) {
        const std::vector<double>& root =
            branch == AuditBranch::published ? definition.continuation_start : definition.second_root_start;
        tracker = BranchTracker{root, std::nullopt, std::nullopt, false};
        if (range.lo != Rational(1, 2)) {
            const FamilyLattice<DInterval> start = enclose_family_at(family, piece_interval(range.lo, range.lo));
            if (start.branches.empty() || (family == Family::D14 && start.status != Outcome::proved))
                throw std::runtime_error(std::string("no root of the ") + to_string(family) +
                                         " equations on the branch at the start of the range");
            const std::size_t index = branch == AuditBranch::published ? 0 : start.branches.size() - 1;
            tracker = BranchTracker{};
            for (const auto& unknown : start.branches[index].unknowns) tracker->root.push_back(mid_double(unknown.value));
        }
    }
    if (family == Family::S6) {
        std::string failure;
        const std::optional<S6Branch> start = s6_anchor(failure);
        if (!start) throw std::runtime_error("S6: no point proof at p = 9/10 to anchor the audit: " + failure);
        tracker = BranchTracker{{}, std::nullopt, start, false};
        result.anchor = start;
    }
    return tracker;
}

}  // namespace

AuditResult audit_family(Family family, const AuditRange& range, const AuditSettings& settings, AuditBranch branch,
                         const AuditProgress& progress) {
    require_audit_input(family, range, branch);
    AuditResult result{family, branch, range, {}, std::nullopt};
    const Rational anchor = s6_seed_p();
    const std::vector<Rational> ends = segment_ends(family, range);
    const Rational total = range.hi - range.lo;
    std::optional<BranchTracker> tracker = continuation(family, range, branch, result);
    const std::optional<BranchTracker> anchored = tracker;
    std::vector<long> counts;
    for (std::size_t k = 0; k + 1 < ends.size(); ++k) {
        const Rational share = (ends[k + 1] - ends[k]) / total * settings.initial_pieces;
        counts.push_back(std::max(1L, static_cast<long>(share.get_d())));
    }
    // Pieces audited or still to be audited: a bisection adds one.
    std::size_t planned = 0;
    for (long count : counts) planned += static_cast<std::size_t>(count);
    if (planned > settings.max_pieces)
        throw InputError("the audit would start with " + std::to_string(planned) + " pieces, more than the limit " +
                         std::to_string(settings.max_pieces));
    AuditDriver driver{family, branch, settings, progress, result, tracker, planned};
    // One segment between ends, its pieces in the order walked.
    auto segment = [&](std::size_t k, bool downward) {
        const long count = counts[k];
        std::vector<AuditSpan> pieces;
        for (long j = 0; j < count; ++j) {
            const long i = downward ? count - 1 - j : j;
            Rational lo = ends[k] + (ends[k + 1] - ends[k]) * i / count, hi = ends[k] + (ends[k + 1] - ends[k]) * (i + 1) / count;
            lo.canonicalize();
            hi.canonicalize();
            pieces.push_back(AuditSpan{lo, hi});
        }
        branch_and_bound(driver, pieces, BranchOptions{});
    };
    if (family != Family::S6) {
        for (std::size_t k = 0; k + 1 < ends.size(); ++k) segment(k, false);
        return result;
    }
    // S6: up from 9/10, then down from 9/10 again (the anchor's box, an unbroken chain).
    for (std::size_t k = 0; k + 1 < ends.size(); ++k)
        if (ends[k] >= anchor) segment(k, false);
    tracker = anchored;
    tracker->downward = true;
    driver.chain_broken = false;
    for (std::size_t k = ends.size() - 1; k-- > 0;)
        if (ends[k + 1] <= anchor) segment(k, true);
    std::sort(result.pieces.begin(), result.pieces.end(),
              [](const AuditPiece& a, const AuditPiece& b) { return a.lo < b.lo; });
    return result;
}

std::vector<AuditPiece> merge_verdict_ranges(const std::vector<AuditPiece>& pieces) {
    std::vector<AuditPiece> merged;
    for (const AuditPiece& piece : pieces) {
        if (!merged.empty()) {
            AuditPiece& last = merged.back();
            if (last.outcome == piece.outcome && last.contacts == piece.contacts && last.witness == piece.witness &&
                last.hi == piece.lo && (piece.outcome != "undecided" || last.reason == piece.reason)) {
                last.hi = piece.hi;
                continue;
            }
        }
        AuditPiece summary{piece.lo, piece.hi, piece.verdict, piece.reason, piece.outcome, piece.contacts, piece.witness, Json(), nullptr, nullptr};
        merged.push_back(summary);
    }
    return merged;
}

std::string audit_file_name(const AuditResult& result) {
    return std::string("proofs/audit-") + to_string(result.family) +
           (result.branch == AuditBranch::o1_second_root ? "-second-root" : "") + ".json";
}

Json audit_json(const AuditResult& result) {
    Json document;
    document["family"] = to_string(result.family);
    // "published" is the branch that defines the family (the paper's equations for C0, C1, O0, O1,
    // Dostert and Vallentin's for D14, superpack's KKT branch for S6), as against O1's second root.
    document["lattice"] = result.branch == AuditBranch::published ? "the family's defining branch (NOTES.md 4)"
                                                                  : "second real root of Eq. (12)";
    document["range"] = Json{{"lo", rational_text(result.range.lo)}, {"hi", rational_text(result.range.hi)}};
    document["range_note"] = result.range.note;
    document["claimed_contacts"] = claimed_contacts(result.family);
    document["criterion"] = "p >= 1/2: translates by u, v have disjoint interiors iff ||u - v||_(2p) >= 2; every "
                            "vector with ||v||_(2p) <= 2 has |a_i| <= 2 ||e_j x e_k||_1 / |det| (NOTES.md section 5)";
    Json verdicts = Json::array();
    for (const AuditPiece& range : merge_verdict_ranges(result.pieces)) {
        Json entry{{"p", Json{{"lo", rational_text(range.lo)}, {"hi", rational_text(range.hi)}}}, {"outcome", range.outcome},
                   {"contacts", range.contacts}};
        if (range.witness) entry["witness"] = coefficients_json(*range.witness);
        if (range.outcome == "undecided") entry["reason"] = range.reason;
        verdicts.push_back(entry);
    }
    document["verdict_ranges"] = verdicts;
    Json pieces = Json::array();
    for (const AuditPiece& piece : result.pieces) {
        Json entry{{"p", Json{{"lo", rational_text(piece.lo)}, {"hi", rational_text(piece.hi)}}},
                   {"outcome", piece.outcome}, {"reason", piece.reason}, {"contacts", piece.contacts}};
        entry["witness"] = piece.witness ? coefficients_json(*piece.witness) : Json(nullptr);
        entry["detail"] = piece.detail;
        pieces.push_back(entry);
    }
    document["pieces"] = pieces;
    return document;
}

}  // namespace superpack
