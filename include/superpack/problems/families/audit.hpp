// Audit of a lattice family over a range of p: the range is cut into pieces with exact rational
// endpoints, and each piece gets one verdict (packing with its contacts, overlapping with a
// witness vector, or undecided with the reason) that holds for every p in the piece.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "superpack/problems/families/family_lattice_check.hpp"
#include "superpack/problems/families/s6_branch.hpp"

namespace superpack {

struct AuditPiece {
    Rational lo, hi;  // the piece [lo, hi] of p, exactly
    Outcome verdict = Outcome::undecided;
    std::string reason;
    // packing | overlapping (every p of the piece) | overlapping_at_point (at the piece's midpoint,
    // the piece itself undecided) | no_lattice | undecided
    std::string outcome = "undecided";
    std::size_t contacts = 0;
    std::optional<Coefficients> witness;
    Json detail;      // parameter boxes, basis, coefficient bound, vectors and norm enclosures
    // The certified family at the piece's p interval and the lattice check behind the verdict
    // (absent when the family was not certified): what an audit certificate is written from.
    std::shared_ptr<const FamilyLattice<DInterval>> lattice;
    std::shared_ptr<const LatticeCheck<DInterval>> check;
};

// Which lattice of a family is audited: the one that defines the family (published for C0, C1,
// O0, O1 and D14; superpack's own KKT branch for S6), or (O1 only) the other real root branch of
// Eq. (12) that the paper says does not exist beyond p*_o.
enum class AuditBranch { published, o1_second_root };

struct AuditRange {
    Rational lo, hi;
    std::vector<Rational> breaks;  // extra piece ends inside (lo, hi), e.g. a bracket of p*_o
    std::string note;  // e.g. how the irrational end p*_o is bracketed
};

// The range the paper claims (C0, C1: [1, 10]; O0: [p*_o, 1]; O1: [1/2, p*_o]), with p*_o
// replaced by a rational bracket that is checked rigorously (the bracketing piece is audited too).
AuditRange claimed_audit_range(Family family);

struct AuditSettings {
    int initial_pieces = 16;
    int max_depth = 12;  // a piece is bisected at most this often when undecided
    // No piece is bisected once the audit would hold more pieces than this: the time and the
    // size of out/audit-<F>.json (up to about 12 kB a piece, as for O1) stay bounded.
    std::size_t max_pieces = 5000;
};

AuditSettings default_audit_settings(Family family);

struct AuditResult {
    Family family;
    AuditBranch branch = AuditBranch::published;
    AuditRange range;
    std::vector<AuditPiece> pieces;  // in order, covering [range.lo, range.hi] without gaps
    std::optional<S6Branch> anchor;  // S6: the point proof at 9/10 that its chain starts from
};

using AuditProgress = std::function<void(const std::string&)>;

AuditResult audit_family(Family family, const AuditRange& range, const AuditSettings& settings,
                         AuditBranch branch = AuditBranch::published, const AuditProgress& progress = {});

// Consecutive pieces with the same verdict (and contact count / witness) merged, for the table.
std::vector<AuditPiece> merge_verdict_ranges(const std::vector<AuditPiece>& pieces);

Json audit_json(const AuditResult& result);
// proofs/audit-<family>.json (or audit-O1-second-root.json), written atomically.
std::string audit_file_name(const AuditResult& result);

}  // namespace superpack
