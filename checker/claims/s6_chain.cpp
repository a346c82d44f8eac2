#include "checker/claims/s6_chain.hpp"

#include "checker/claims/family_parameters.hpp"
#include "checker/formulas/equations_kkt.hpp"
#include "checker/formulas/kkt_point.hpp"

namespace superpack_checker {

mpq_class s6_anchor_p() { return mpq_class(9, 10); }

namespace {

// The unique KKT point in `box` at the one point p, tightened; nothing if not proved.
std::optional<Box> root_at(const Box& box, const mpq_class& p, mpfr_prec_t precision) {
    try {
        const KrawczykReplay replay = replay_krawczyk(kkt_system(KktEquations{s6_triples(), rational(p, precision)}), box, 80);
        if (replay.status == ReplayStatus::unique) return replay.root;
    } catch (const UnboundedPower&) {
    }
    return std::nullopt;
}

// One piece's box: exactly one KKT point for every p of the piece (rejects otherwise); returns
// the box and the checker's root over the piece.
std::pair<Box, Box> replay_piece(Context& context, const Json& node, const std::string& path, const PieceEnds& piece) {
    const mpfr_prec_t precision = context.precision();
    context.current_step = path;
    if (context.string_at(node, "kind", path) != "krawczyk" || context.string_at(node, "status", path) != "unique")
        context.malformed(path, "expected a krawczyk leaf with status unique");
    const Box box = context.box(context.member(node, "box", path), path + ".box");
    if (box.size() != 9 + s6_triples().size()) context.malformed(path + ".box", "expected the 15 unknowns (B, mu)");
    const mpq_class p0 = context.rational_at(node, "p0", path);
    context.require(piece.lo <= p0 && p0 <= piece.hi, path + ".p0", "the midpoint p0 is not in the piece");
    const Real p = hull(rational(piece.lo, precision), rational(piece.hi, precision)), at = rational(p0, precision);
    const KktEquations over_piece{s6_triples(), p}, at_p0{s6_triples(), at};
    const ParameterForm form{[at_p0](const Box& x) { return at_p0.value(x); },
                             [over_piece](const Box& x) { return over_piece.p_derivative(x); }, p - at};
    KrawczykReplay replay;
    try {
        replay = replay_krawczyk(kkt_system(over_piece), box, 80, &form);
    } catch (const UnboundedPower& error) {
        context.reject(path + ".box", std::string("a contact coordinate may be 0 on the box: ") + error.what());
    }
    context.require(replay.status == ReplayStatus::unique, path,
                    "the checker could not prove exactly one KKT point in the box for every p of the piece (" +
                        replay.reason + ")");
    const Box stored_root = context.box(context.member(node, "root", path), path + ".root");
    context.require(stored_root.size() == box.size(), path + ".root", "wrong dimension");
    for (std::size_t k = 0; k < box.size(); ++k)
        context.require(subset(replay.root[k], stored_root[k]), path + ".root[" + std::to_string(k) + "]",
                        "the stored root box " + text(stored_root[k]) + " does not hold the root " + text(replay.root[k]));
    return {box, replay.root};
}

}  // namespace

std::vector<std::optional<Box>> replay_s6_chain(Context& context, const std::vector<PieceEnds>& pieces, const Json& proofs,
                                                const Json& anchor) {
    const mpfr_prec_t precision = context.precision();
    const mpq_class at = s6_anchor_p();
    // Rejects at proof.anchor unless its box holds exactly one KKT point at p = 9/10.
    replay_kkt_point(context, s6_triples(), anchor, "proof.anchor", rational(at, precision));
    const Box anchor_box = context.box(context.member(anchor, "box", "proof.anchor"), "proof.anchor.box");
    std::optional<std::size_t> up, down;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        if (pieces[k].lo == at) up = k;
        if (pieces[k].hi == at) down = k;
    }
    context.require(up || down, "claim.data.pieces",
                    "p = 9/10, where the S6 branch is anchored by its point proof, is not an end of a piece");
    std::vector<std::optional<Box>> roots(pieces.size());
    // Walks from `start` in steps of `step` (+1 up, -1 down), linking at the end nearer 9/10.
    auto walk = [&](std::size_t start, int step) {
        Box previous = anchor_box;
        for (std::size_t k = start; k < pieces.size(); k += static_cast<std::size_t>(step)) {
            const std::string path = "proof.pieces[" + std::to_string(k) + "].parameters";
            const Json& node = context.member(proofs[k], "parameters", "proof.pieces[" + std::to_string(k) + "]");
            if (node.is_null()) return;
            const auto [box, root] = replay_piece(context, node, path, pieces[k]);
            const mpq_class& shared = step > 0 ? pieces[k].lo : pieces[k].hi;
            const std::optional<Box> end = root_at(box, shared, precision);
            if (!end || !box_inside(*end, previous)) return;
            roots[k] = root;
            previous = box;
            if (k == 0 && step < 0) return;
        }
    };
    if (up) walk(*up, 1);
    if (down) walk(*down, -1);
    return roots;
}

}  // namespace superpack_checker
