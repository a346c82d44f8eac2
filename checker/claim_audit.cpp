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
// then the verdict with the checker's own enumeration (family_verdict.hpp).
//
// Keys read: claim.data {family, lattice ("published"), range {lo, hi}, pieces [{p {lo, hi},
// verdict, contacts, contact_vectors | witness | at, witness}]}; inputs {family, range};
// proof {kind, pieces [{parameters, lattice}]} (both null where nothing is proved).
#include <optional>

#include "checker/family_verdict.hpp"
#include "checker/literature.hpp"
#include "checker/render.hpp"

namespace superpack_checker {

namespace {

struct Piece {
    mpq_class lo, hi;
};

Piece read_piece_range(Context& context, const Json& node, const std::string& path) {
    Piece piece{context.rational_at(node, "lo", path), context.rational_at(node, "hi", path)};
    context.require(piece.lo < piece.hi, path, "an empty piece (lo >= hi)");
    return piece;
}

// Minkowski's lattice: (q, s) = (1/6, 2/3) solves Eq. (12) at p = 1/2 (l = 1/3), exactly.
bool minkowski_solves_eq12() {
    const mpq_class q(1, 6), s(2, 3), l(1, 3);
    return 2 * abs(q) + abs(s) == 1 && abs(l + q) + abs(s - l) + abs(l - q) == 1;
}

// The O1 continuation state: the box of the previous piece, when the chain is unbroken.
struct Chain {
    std::optional<Box> previous;
};

// The symbols of the O1 basis from the root box of Eq. (12) at p.
NamedReals o1_symbols(const Box& root, const Real& p) {
    return NamedReals{{"l", OctahedralEquations{p}.l()}, {"q", root[0]}, {"s", root[1]}};
}

// The unique root of Eq. (12) in `box` at the single point p0 (the box holds the branch for
// every p of its piece, p0 among them), tightened by Krawczyk.
Box o1_root_at(Context& context, const Box& box, const Real& p0, const std::string& path) {
    const KrawczykReplay replay = replay_krawczyk(octahedral_system(p0), box, 80);
    context.require(replay.status == ReplayStatus::unique, path, "no unique root in the box at the point p = " + text(p0));
    return replay.root;
}

struct O1Piece {
    Box box;   // the stored box: exactly one root for every p of the piece
    Box root;  // the checker's tightened box of that root over the piece
};

// Replays the O1 box of one piece; returns it, or nothing when the chain to p = 1/2 is broken
// (the piece then cannot be decided).
std::optional<O1Piece> replay_o1_piece(Context& context, const Json& node, const std::string& path, const Piece& piece,
                                          const Real& p, Chain& chain, bool first) {
    const mpfr_prec_t precision = p.precision();
    if (node.is_null()) {
        chain.previous.reset();
        return std::nullopt;
    }
    context.current_step = path;
    if (context.string_at(node, "kind", path) != "krawczyk" || context.string_at(node, "status", path) != "unique")
        context.malformed(path, "expected a krawczyk leaf with status unique");
    const Box box = context.box(context.member(node, "box", path), path + ".box");
    if (box.size() != 2) context.malformed(path + ".box", "expected a (q, s) box");
    const KrawczykReplay replay = replay_krawczyk(octahedral_system(p), box, 80);
    context.require(replay.status == ReplayStatus::unique, path,
                    "the checker could not prove exactly one root in the box for every p of the piece (" + replay.reason + ")");
    bool linked = false;
    if (first) {
        const mpq_class half(1, 2);
        linked = piece.lo == half && minkowski_solves_eq12() && subset(rational(mpq_class(1, 6), precision), box[0]) &&
                 subset(rational(mpq_class(2, 3), precision), box[1]);
    } else if (chain.previous) {
        const Box at_end = o1_root_at(context, box, rational(piece.lo, precision), path);
        linked = subset(at_end[0], (*chain.previous)[0]) && subset(at_end[1], (*chain.previous)[1]);
    }
    chain.previous = box;
    if (!linked) {
        chain.previous.reset();
        return std::nullopt;
    }
    return O1Piece{box, replay.root};
}

// A run of consecutive pieces with the same verdict words, for the sentence.
struct MergedRange {
    mpq_class lo, hi;
    std::string words;
};

void merge(std::vector<MergedRange>& ranges, const Piece& piece, const std::string& words) {
    if (!ranges.empty() && ranges.back().words == words && ranges.back().hi == piece.lo)
        ranges.back().hi = piece.hi;
    else
        ranges.push_back({piece.lo, piece.hi, words});
}

std::string check_audit(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const Json& proof = context.member(document, "proof", "");
    const mpfr_prec_t precision = context.precision();
    const std::string family = read_family(context, data, inputs);
    const Piece range = read_piece_range(context, context.member(data, "range", "claim.data"), "claim.data.range");
    const Piece input_range = read_piece_range(context, context.member(inputs, "range", "inputs"), "inputs.range");
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
    const FamilyForms forms = family_forms(family);

    Chain chain;
    std::vector<MergedRange> merged;
    bool refutes_o1 = false;  // an O1 piece overlapping for every p, below p*_o
    const Real crossover = log(integer(3, precision)) / log(integer(4, precision));
    mpq_class reached = range.lo;  // the pieces so far cover [range.lo, reached]
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const std::string claim_path = "claim.data.pieces[" + std::to_string(k) + "]";
        const std::string proof_path = "proof.pieces[" + std::to_string(k) + "]";
        const Piece piece = read_piece_range(context, context.member(pieces[k], "p", claim_path), claim_path + ".p");
        context.require(piece.lo == reached, claim_path + ".p",
                        piece.lo > reached ? "a gap in the cover of the range" : "the pieces overlap or are out of order");
        reached = piece.hi;
        const Real p = hull(rational(piece.lo, precision), rational(piece.hi, precision));
        const std::string verdict = context.string_at(pieces[k], "verdict", claim_path);
        const bool decided = verdict != "undecided";
        // overlapping_at_point: the claim is about the one point p = at of the piece.
        const bool at_point = verdict == "overlapping_at_point";
        std::optional<mpq_class> at;
        if (at_point) {
            at = context.rational_at(pieces[k], "at", claim_path);
            context.require(piece.lo <= *at && *at <= piece.hi, claim_path + ".at", "the point is not in the piece");
        }
        const Real p_claimed = at ? rational(*at, precision) : p;
        const std::string parameters_path = proof_path + ".parameters";
        const Json& parameters = context.member(proofs[k], "parameters", proof_path);
        const Json& lattice = context.member(proofs[k], "lattice", proof_path);
        if (!decided) {
            merge(merged, piece, "undecided");
            // Nothing is proved here: no lattice proof (O1 keeps its box for the chain, below).
            if (!lattice.is_null()) context.malformed(proof_path + ".lattice", "an undecided piece proves nothing: expected null");
            if (family != "O1" && !parameters.is_null())
                context.malformed(parameters_path, "an undecided piece proves nothing: expected null");
        }
        NamedReals symbols;
        if (family == "O1") {
            const auto replayed = replay_o1_piece(context, parameters, parameters_path, piece, p, chain, k == 0);
            if (!decided) continue;
            context.require(replayed.has_value(), parameters_path,
                            "the branch through (1/6, 2/3) at p = 1/2 is not followed onto this piece");
            symbols = o1_symbols(at ? o1_root_at(context, replayed->box, p_claimed, parameters_path) : replayed->root, p_claimed);
        } else {
            if (!decided) continue;
            context.require(!parameters.is_null(), parameters_path, "a decided piece needs its parameter proof");
            // The piece's proof holds for every p of the piece, so also at the point.
            symbols = replay_family_parameters(context, family, parameters, parameters_path, p_claimed, claim_path + ".p").symbols;
        }
        const FamilyVerdict result = check_family_verdict(context, forms, symbols, p_claimed, at_point ? "overlapping" : verdict,
                                                          pieces[k], claim_path, lattice, proof_path + ".lattice");
        if (at_point)
            merge(merged, piece, "undecided, but overlapping at one certified point per piece (witness " + triple_text(result.witness) + ")");
        else if (result.packing)
            merge(merged, piece, "packing with " + std::to_string(result.contacts) + " contacts");
        else
            merge(merged, piece, "overlapping (witness " + triple_text(result.witness) + ")");
        refutes_o1 = refutes_o1 || (family == "O1" && !result.packing && !at_point &&
                                    less(rational(piece.hi, precision), crossover));
    }
    context.require(reached == range.hi, "claim.data.pieces", "the pieces stop before the end of the range");

    // The sentence, from the verdicts verified above.
    const std::string lattice_text =
        family == "O1" ? std::string("the O1 lattice of ") + paper_citation +
                             " (Sec. IV.B: basis Eq. (15), (q, s) on the root branch of Eq. (16) through Minkowski's (1/6, 2/3) "
                             "at p = 1/2)"
                       : lattice_words(family);
    std::string text = "For every p in each piece [lo, hi] of claim.data.pieces (exact rational ends; the pieces cover [" +
                       rational_words(range.lo) + ", " + rational_words(range.hi) + "] without gaps), " + lattice_text +
                       " has the verdict stated for the piece: a packing of the superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1 "
                       "with the stated contacts, or not a packing (the witness vector has 2p-norm < 2). A piece marked "
                       "overlapping_at_point is not a packing at the one point p = at of the piece (witness) and proves "
                       "nothing about its other p. Pieces marked undecided prove nothing.";
    if (family == "O1")
        text += " The branch is followed by continuation: a Krawczyk box per piece, each holding the root of the next "
                "piece at their shared end; a piece without a box breaks the chain.";
    text += " The verdicts, merged:";
    for (const MergedRange& entry : merged)
        text += " [" + rational_words(entry.lo) + ", " + rational_words(entry.hi) + "] " + entry.words + ";";
    text.back() = '.';
    if (refutes_o1) text += refutation_words(o1_packs);
    return text;
}

const ClaimKindRegistration registration("audit", check_audit);

}  // namespace

}  // namespace superpack_checker
