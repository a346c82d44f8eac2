// Claim kind "audit" (written by `superpack audit --family F --certificate FILE`): the range
// [lo, hi] of p is cut into pieces with exact rational ends, each with a verdict that holds for
// EVERY p of the piece: packing with k contacts, or overlapping with a witness vector; or
// overlapping_at_point: not a packing at the one stated point p = at of the piece. Pieces
// marked undecided carry their reason and prove nothing. The checker requires the pieces to
// cover the range without gaps and replays each decided piece with p as an MPFI interval:
//   C0, C1, O0: the family's parameter proof at interval p (replay_family_parameters: Newton
//               and the root-free partition hold for every p of the piece);
//   O1:         a Krawczyk box of Eq. (12) holding exactly one root for every p of the piece.
//               Which root is the branch through Minkowski's (q, s) = (1/6, 2/3) at p = 1/2,
//               checked by continuation: the first piece starts at p = 1/2 with that point (a
//               root, checked exactly) in its box, and at each shared end p0 the root of the
//               next box (Krawczyk at the point p0) lies in the previous box, where the root at
//               p0 is unique. The root is continuous on each piece (Krawczyk proves the
//               Jacobian nonsingular), so the boxes follow one branch. A piece without a box
//               breaks the chain: no later O1 piece can be decided.
//   D14:        the same continuation for the equations of Dostert and Vallentin (2020) in
//               (x, y, z), from the exact root (1/3, 1/6, 1/2) at p = 1/2.
//   S6:         the same for the KKT system of the six triples, from the point proof at
//               p = 9/10 (proof.anchor) up and down, each box replayed with the mean-value
//               form in p about its stored midpoint p0 (s6_chain.hpp).
// then the verdict with the checker's own enumeration (family_verdict.hpp).
//
// Keys read: claim.data {family, lattice ("published"), range {lo, hi}, pieces [{p {lo, hi},
// verdict, contacts, contact_vectors | witness | at, witness}]}; inputs {family, range};
// proof {kind, pieces [{parameters, lattice}]} (both null where nothing is proved); S6 also
// claim.data.contact_pairs and proof.anchor (a Krawczyk leaf at p = 9/10).
#include <optional>

#include "checker/claims/family_verdict.hpp"
#include "checker/claims/literature.hpp"
#include "checker/core/render.hpp"
#include "checker/formulas/equations_kkt.hpp"
#include "checker/claims/family_parameters.hpp"
#include "checker/claims/s6_chain.hpp"

namespace superpack_checker {

namespace {

PieceEnds read_piece_range(Context& context, const Json& node, const std::string& path) {
    PieceEnds piece{context.rational_at(node, "lo", path), context.rational_at(node, "hi", path)};
    context.require(piece.lo < piece.hi, path, "an empty piece (lo >= hi)");
    return piece;
}

// Minkowski's lattice: (q, s) = (1/6, 2/3) solves Eq. (12) at p = 1/2 (l = 1/3), exactly; as
// D14 it is (x, y, z) = (1/3, 1/6, 1/2), which solves the D14 equations at p = 1/2 exactly.
bool minkowski_solves_eq12() {
    const mpq_class q(1, 6), s(2, 3), l(1, 3);
    return 2 * abs(q) + abs(s) == 1 && abs(l + q) + abs(s - l) + abs(l - q) == 1;
}

bool minkowski_solves_d14() {
    const mpq_class x(1, 3), y(1, 6), z(1, 2);
    return abs(x) + abs(y) + abs(z) == 1 && abs(x - y) + abs(z - x) + abs(y + z) == 1 && 3 * abs(y + z - x) == 1;
}

// The families audited by continuation, their systems and their start at p = 1/2.
bool continued(const std::string& family) { return family == "O1" || family == "D14"; }

System continuation_system(const std::string& family, const Real& p) {
    return family == "O1" ? octahedral_system(p) : d14_system(p);
}

std::vector<mpq_class> continuation_start(const std::string& family) {
    if (family == "O1") return {mpq_class(1, 6), mpq_class(2, 3)};
    return {mpq_class(1, 3), mpq_class(1, 6), mpq_class(1, 2)};
}

// The O1 or D14 continuation state: the box of the previous piece, when the chain is unbroken.
struct Chain {
    std::optional<Box> previous;
};

// The symbols of the basis from the root box at p: O1 (Eq. (12)) or D14.
NamedReals continued_symbols(const std::string& family, const Box& root, const Real& p) {
    if (family == "O1") return NamedReals{{"l", OctahedralEquations{p}.l()}, {"q", root[0]}, {"s", root[1]}};
    return NamedReals{{"x", root[0]}, {"y", root[1]}, {"z", root[2]}};
}

// The unique root in `box` at the single point p0 (the box holds the branch for every p of its
// piece, p0 among them), tightened by Krawczyk.
Box root_at(Context& context, const std::string& family, const Box& box, const Real& p0, const std::string& path) {
    const KrawczykReplay replay = replay_krawczyk(continuation_system(family, p0), box, 80);
    context.require(replay.status == ReplayStatus::unique, path, "no unique root in the box at the point p = " + text(p0));
    return replay.root;
}

struct ContinuedPiece {
    Box box;   // the stored box: exactly one root for every p of the piece
    Box root;  // the checker's tightened box of that root over the piece
};

// Replays the O1 or D14 box of one piece; returns it, or nothing when the chain to p = 1/2 is
// broken (the piece then cannot be decided).
std::optional<ContinuedPiece> replay_continued_piece(Context& context, const std::string& family, const Json& node,
                                                     const std::string& path, const PieceEnds& piece, const Real& p, Chain& chain,
                                                     bool first) {
    const mpfr_prec_t precision = p.precision();
    if (node.is_null()) {
        chain.previous.reset();
        return std::nullopt;
    }
    context.current_step = path;
    if (context.string_at(node, "kind", path) != "krawczyk" || context.string_at(node, "status", path) != "unique")
        context.malformed(path, "expected a krawczyk leaf with status unique");
    const Box box = context.box(context.member(node, "box", path), path + ".box");
    const std::vector<mpq_class> start = continuation_start(family);
    if (box.size() != start.size()) context.malformed(path + ".box", family == "O1" ? "expected a (q, s) box" : "expected an (x, y, z) box");
    const KrawczykReplay replay = replay_krawczyk(continuation_system(family, p), box, 80);
    context.require(replay.status == ReplayStatus::unique, path,
                    "the checker could not prove exactly one root in the box for every p of the piece (" + replay.reason + ")");
    bool linked = false;
    if (first) {
        const mpq_class half(1, 2);
        linked = piece.lo == half && (family == "O1" ? minkowski_solves_eq12() : minkowski_solves_d14());
        for (std::size_t k = 0; k < start.size(); ++k) linked = linked && subset(rational(start[k], precision), box[k]);
    } else if (chain.previous) {
        const Box at_end = root_at(context, family, box, rational(piece.lo, precision), path);
        linked = box_inside(at_end, *chain.previous);
    }
    chain.previous = box;
    if (!linked) {
        chain.previous.reset();
        return std::nullopt;
    }
    return ContinuedPiece{box, replay.root};
}

// A run of consecutive pieces with the same verdict words, for the sentence.
struct MergedRange {
    mpq_class lo, hi;
    std::string words;
};

void merge(std::vector<MergedRange>& ranges, const PieceEnds& piece, const std::string& words) {
    if (!ranges.empty() && ranges.back().words == words && ranges.back().hi == piece.lo)
        ranges.back().hi = piece.hi;
    else
        ranges.push_back({piece.lo, piece.hi, words});
}

// The S6 chain's root boxes, one per piece (nullopt where the chain does not reach): the branch
// is followed from the point proof at p = 9/10 over all pieces before any piece is checked.
std::vector<std::optional<Box>> replay_s6_roots(Context& context, const Json& pieces, const Json& proof,
                                                const Json& proofs) {
    std::vector<PieceEnds> ends;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const std::string claim_path = "claim.data.pieces[" + std::to_string(k) + "]";
        ends.push_back(read_piece_range(context, context.member(pieces[k], "p", claim_path), claim_path + ".p"));
    }
    return replay_s6_chain(context, ends, proofs, context.member(proof, "anchor", "proof"));
}

// The walk over an audit's pieces in order: they cover the range without gaps; each decided
// piece gets its parameters by the family's kind of proof (S6 chain, continuation, or its own
// parameter proof) and its verdict replayed; the verdicts are merged for the sentence.
class AuditWalk {
public:
    AuditWalk(Context& context, const std::string& family, const FamilyForms& forms,
              std::vector<std::optional<Box>> s6_roots, const mpq_class& start)
        : context_(context), family_(family), s6_(family == "S6"), forms_(forms), s6_roots_(std::move(s6_roots)),
          precision_(context.precision()), crossover_(log(integer(3, precision_)) / log(integer(4, precision_))),
          reached_(start) {}

    // Piece k: its place in the cover, its verdict, and what the verdict rests on.
    void check_piece(const Json& claimed, const Json& proof, std::size_t k) {
        const std::string claim_path = "claim.data.pieces[" + std::to_string(k) + "]";
        const std::string proof_path = "proof.pieces[" + std::to_string(k) + "]";
        const PieceEnds piece = read_piece_range(context_, context_.member(claimed, "p", claim_path), claim_path + ".p");
        context_.require(piece.lo == reached_, claim_path + ".p",
                         piece.lo > reached_ ? "a gap in the cover of the range" : "the pieces overlap or are out of order");
        reached_ = piece.hi;
        const Real p = hull(rational(piece.lo, precision_), rational(piece.hi, precision_));
        const std::string verdict = context_.string_at(claimed, "verdict", claim_path);
        const bool decided = verdict != "undecided";
        // overlapping_at_point: the claim is about the one point p = at of the piece.
        const bool at_point = verdict == "overlapping_at_point";
        std::optional<mpq_class> at;
        if (at_point) {
            at = context_.rational_at(claimed, "at", claim_path);
            context_.require(piece.lo <= *at && *at <= piece.hi, claim_path + ".at", "the point is not in the piece");
        }
        const Real p_claimed = at ? rational(*at, precision_) : p;
        const std::string parameters_path = proof_path + ".parameters";
        const Json& parameters = context_.member(proof, "parameters", proof_path);
        const Json& lattice = context_.member(proof, "lattice", proof_path);
        if (!decided) {
            merge(merged_, piece, "undecided");
            // Nothing is proved here: no lattice proof (O1, D14 keep their box for the chain, below).
            if (!lattice.is_null()) context_.malformed(proof_path + ".lattice", "an undecided piece proves nothing: expected null");
            if (!continued(family_) && !s6_ && !parameters.is_null())
                context_.malformed(parameters_path, "an undecided piece proves nothing: expected null");
        }
        const std::optional<NamedReals> symbols =
            piece_symbols(parameters, parameters_path, piece, p, p_claimed, decided, at_point, claim_path, k);
        if (!symbols) return;
        const FamilyVerdict result = check_family_verdict(context_, forms_, *symbols, p_claimed, at_point ? "overlapping" : verdict,
                                                          claimed, claim_path, lattice, proof_path + ".lattice");
        if (at_point)
            merge(merged_, piece, "undecided, but overlapping at one certified point per piece (witness " + triple_text(result.witness) + ")");
        else if (result.packing)
            merge(merged_, piece, "packing with " + std::to_string(result.contacts) + " contacts");
        else
            merge(merged_, piece, "overlapping (witness " + triple_text(result.witness) + ")");
        refutes_o1_ = refutes_o1_ || (family_ == "O1" && !result.packing && !at_point &&
                                      less(rational(piece.hi, precision_), crossover_));
    }

    const mpq_class& reached() const { return reached_; }
    const std::vector<MergedRange>& merged() const { return merged_; }
    // An O1 piece overlapping for every p, below p*_o.
    bool refutes_o1() const { return refutes_o1_; }

private:
    // The family's symbols on piece k at p_claimed (the piece's p, or its point `at`), by the
    // family's kind of proof; nullopt for an undecided piece, after the continuation has
    // still replayed its box (an undecided piece may carry the chain on).
    std::optional<NamedReals> piece_symbols(const Json& parameters, const std::string& parameters_path, const PieceEnds& piece,
                                            const Real& p, const Real& p_claimed, bool decided, bool at_point,
                                            const std::string& claim_path, std::size_t k) {
        NamedReals symbols;
        if (s6_) {
            if (!decided) return std::nullopt;
            context_.require(!at_point, claim_path + ".verdict", "S6 pieces are decided for every p of the piece or not at all");
            context_.require(s6_roots_[k].has_value(), parameters_path,
                             "the S6 branch through the point proof at p = 9/10 is not followed onto this piece");
            const std::vector<std::string> names = kkt_symbols();
            for (std::size_t i = 0; i < names.size(); ++i) symbols.push_back({names[i], (*s6_roots_[k])[i]});
        } else if (continued(family_)) {
            const auto replayed = replay_continued_piece(context_, family_, parameters, parameters_path, piece, p, chain_, k == 0);
            if (!decided) return std::nullopt;
            context_.require(replayed.has_value(), parameters_path,
                             std::string("the branch through ") + (family_ == "O1" ? "(1/6, 2/3)" : "(1/3, 1/6, 1/2)") +
                                 " at p = 1/2 is not followed onto this piece");
            symbols = continued_symbols(
                family_, at_point ? root_at(context_, family_, replayed->box, p_claimed, parameters_path) : replayed->root,
                p_claimed);
        } else {
            if (!decided) return std::nullopt;
            context_.require(!parameters.is_null(), parameters_path, "a decided piece needs its parameter proof");
            // The piece's proof holds for every p of the piece, so also at the point.
            symbols = replay_family_parameters(context_, family_, parameters, parameters_path, p_claimed, claim_path + ".p").symbols;
        }
        return symbols;
    }

    Context& context_;
    const std::string family_;
    const bool s6_;
    const FamilyForms& forms_;
    const std::vector<std::optional<Box>> s6_roots_;
    const mpfr_prec_t precision_;
    const Real crossover_;
    mpq_class reached_;  // the pieces so far cover [range.lo, reached_]
    Chain chain_;
    std::vector<MergedRange> merged_;
    bool refutes_o1_ = false;
};

// The sentence, from the verdicts verified by the walk.
std::string audit_sentence(const std::string& family, const PieceEnds& range, const AuditWalk& walk) {
    const bool s6 = family == "S6";
    const std::string lattice_text =
        family == "O1" ? std::string("the O1 lattice of ") + paper_citation +
                             " (Sec. IV.B: basis Eq. (15), (q, s) on the root branch of Eq. (16) through Minkowski's (1/6, 2/3) "
                             "at p = 1/2)"
        : family == "D14" ? std::string("the D14 lattice of ") + dostert_vallentin_citation +
                                " (Theorem 4.2, their exponent 2p: basis 2(-x, y, z), 2(z, -x, y), 2(y, z, -x), (x, y, z) on the "
                                "root branch of their three equations through Minkowski's (1/3, 1/6, 1/2) at p = 1/2)"
        : s6 ? "the S6 lattice (superpack's own family, NOTES.md 4.2; not a published one): the basis B of the KKT point of "
               "min det B subject to ||c B||_(2p) = 2 for Minkowski's six pairs (configuration A3) c = (1,0,0), (0,1,0), "
               "(0,0,1), (0,1,-1), (1,0,-1), (1,-1,0), on the branch through the KKT point at p = 9/10 that is unique in "
               "the box of proof.anchor"
             : lattice_words(family);
    std::string text = "For every p in each piece [lo, hi] of claim.data.pieces (exact rational ends; the pieces cover [" +
                       rational_words(range.lo) + ", " + rational_words(range.hi) + "] without gaps), " + lattice_text +
                       " has the verdict stated for the piece: a packing of the superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1 "
                       "with the stated contacts, or not a packing (the witness vector has 2p-norm < 2). A piece marked "
                       "overlapping_at_point is not a packing at the one point p = at of the piece (witness) and proves "
                       "nothing about its other p. Pieces marked undecided prove nothing.";
    if (s6)
        text += " The branch is followed from p = 9/10 up and down: per piece a Krawczyk box holding exactly one KKT point "
                "for every p of the piece (mean-value form in p), each holding at its end nearer 9/10 the root of the box "
                "before; a piece without a box breaks the chain on its side.";
    if (continued(family))
        text += " The branch is followed by continuation: a Krawczyk box per piece, each holding the root of the next "
                "piece at their shared end; a piece without a box breaks the chain.";
    text += " The verdicts, merged:";
    for (const MergedRange& entry : walk.merged())
        text += " [" + rational_words(entry.lo) + ", " + rational_words(entry.hi) + "] " + entry.words + ";";
    text.back() = '.';
    if (walk.refutes_o1()) text += refutation_words(o1_packs);
    return text;
}

std::string check_audit(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const Json& proof = context.member(document, "proof", "");
    const std::string family = read_family(context, data, inputs);
    check_family_definition(context, family, data);
    const PieceEnds range = read_piece_range(context, context.member(data, "range", "claim.data"), "claim.data.range");
    const PieceEnds input_range = read_piece_range(context, context.member(inputs, "range", "inputs"), "inputs.range");
    context.require(input_range.lo == range.lo && input_range.hi == range.hi, "inputs.range",
                    "the input range differs from the claim's");
    require_family_domain(context, family, range.lo, range.hi, "inputs.range");
    if (context.string_at(data, "lattice", "claim.data") != "published")
        context.malformed("claim.data.lattice", "expected \"published\" (the lattice of the paper)");
    if (context.string_at(proof, "kind", "proof") != "audit") context.malformed("proof.kind", "expected \"audit\"");
    const Json& pieces = context.member(data, "pieces", "claim.data");
    const Json& proofs = context.member(proof, "pieces", "proof");
    if (!pieces.is_array() || !proofs.is_array()) context.malformed("claim.data.pieces", "expected arrays of pieces");
    context.require(!pieces.empty(), "claim.data.pieces", "no pieces");
    context.require(proofs.size() == pieces.size(), "proof.pieces", "one proof per piece of the claim is needed");
    const FamilyForms forms = lattice_forms(family);
    std::vector<std::optional<Box>> s6_roots;
    if (family == "S6") s6_roots = replay_s6_roots(context, pieces, proof, proofs);

    AuditWalk walk(context, family, forms, std::move(s6_roots), range.lo);
    for (std::size_t k = 0; k < pieces.size(); ++k) walk.check_piece(pieces[k], proofs[k], k);
    context.require(walk.reached() == range.hi, "claim.data.pieces", "the pieces stop before the end of the range");
    return audit_sentence(family, range, walk);
}

const ClaimKindRegistration registration("audit", check_audit);

}  // namespace

}  // namespace superpack_checker
