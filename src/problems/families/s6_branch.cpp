#include "superpack/problems/families/s6_branch.hpp"

#include <cmath>

#include "superpack/arith/contract.hpp"

#include "superpack/problems/optimality/local_optimality.hpp"
#include "superpack/problems/families/s6_definition.hpp"

namespace superpack {

namespace {

const std::vector<Coefficients>& triples() { return s6_contact_triples(); }

std::vector<double> unknowns(const KktPoint& point) {
    std::vector<double> x;
    for (const auto& row : point.basis) x.insert(x.end(), row.begin(), row.end());
    x.insert(x.end(), point.multipliers.begin(), point.multipliers.end());
    return x;
}

}  // namespace

std::optional<S6Branch> s6_anchor(std::string& failure) {
    const std::optional<KktPoint> guess = s6_guess(s6_seed_p().get_d(), failure);
    if (!guess) return std::nullopt;
    const KrawczykResult<DInterval> proof = isolate_kkt_point(*guess, triples(), DoubleField{}.rational(s6_seed_p()));
    if (proof.status != RootStatus::unique) {
        failure = "Krawczyk did not prove the KKT point at p = 9/10 (" + proof.reason + ")";
        return std::nullopt;
    }
    return S6Branch{*guess, proof.initial_box, proof.box};
}

bool s6_linked(const std::vector<DInterval>& box, const std::vector<DInterval>& previous, const Rational& p) {
    const DInterval at = DoubleField{}.rational(p);
    // A refused enclosure proves no link.
    return within_contract([&] {
               return unique_root_within([&](const auto& x) { return kkt_equations(x, triples(), at); }, box, previous);
           }).value.value_or(false);
}

S6Piece s6_piece(S6Branch& branch, const Rational& lo, const Rational& hi, const Rational& shared) {
    const DoubleField field;
    S6Piece piece;
    piece.p0 = (lo + hi) / 2;
    piece.p0.canonicalize();
    const std::optional<KktPoint> guess = kkt_point(branch.guess, piece.p0.get_d(), triples());
    if (!guess) {
        piece.reason = "Newton's method lost the KKT point at the piece's midpoint";
        return piece;
    }
    const DInterval p = hull(field.rational(lo), field.rational(hi)), p0 = field.rational(piece.p0);
    const double w = Rational(hi - lo).get_d() / 2;
    // The point moves by about |dx/dp| w over the half-piece (|dx/dp| <= 7.1 on [0.85, 0.95]):
    // a box a few times that wide about the guess, plus a margin for the guess's own error.
    const std::vector<double> x = unknowns(*guess);
    auto equations = [&](const auto& y, const auto& q) { return kkt_equations(y, triples(), q); };
    for (const double scale : {10.0, 16.0, 32.0}) {
        std::vector<DInterval> box;
        for (double value : x) {
            const double radius = scale * w + 1e-10 * std::max(1.0, std::fabs(value));
            box.push_back(from_doubles(field.integer(0), value - radius, value + radius));
        }
        const Contracted<KrawczykResult<DInterval>> isolated =
            within_contract([&] { return krawczyk_isolate_in_parameter(equations, box, p, p0, 0.0, 60); });
        if (isolated.status == ContractStatus::too_wide) {
            piece.reason = isolated.reason();
            continue;
        }
        const KrawczykResult<DInterval>& proof = *isolated.value;
        if (proof.status != RootStatus::unique) {
            piece.reason = "Krawczyk did not prove one KKT point for every p of the piece (" + proof.reason + ")";
            continue;
        }
        if (!s6_linked(box, branch.box, shared)) {
            piece.reason = "the box does not hold, at the shared end, the root of the box before it";
            continue;
        }
        piece.status = RootStatus::unique;
        piece.reason = "K(X, P) in the interior of X (mean-value form in p), linked to the box before";
        piece.box = box;
        piece.root = proof.box;
        branch = S6Branch{*guess, box, proof.box};
        return piece;
    }
    return piece;
}

}  // namespace superpack
