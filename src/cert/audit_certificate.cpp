#include "superpack/cert/audit_certificate.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "superpack/arith/decimal.hpp"
#include "superpack/cert/certificate_partition.hpp"
#include "superpack/cert/family_certificate.hpp"
#include "superpack/problems/families/family_registry.hpp"
#include "superpack/problems/families/s6_branch.hpp"

namespace superpack {

namespace {

// O1, a piece whose audit refuted the packing at its midpoint p0 only: the root at p0 from the
// piece's own Krawczyk box (which holds the branch for every p of the piece), and the lattice
// check at that one p. The verdict {"verdict": "overlapping_at_point", "at", "witness"}, or
// nothing when the refutation does not reproduce.
std::optional<Json> o1_point_refutation(const AuditPiece& piece) {
    Rational middle = (piece.lo + piece.hi) / 2;
    middle.canonicalize();
    const DoubleField field;
    const DInterval p = field.rational(middle);
    auto equations = [&](const auto& x) { return o1_equations(x, p); };
    const KrawczykResult<DInterval> root = krawczyk_isolate(equations, piece.lattice->search.back().piece, 0.0, 60);
    if (root.status != RootStatus::unique) return std::nullopt;
    const std::vector<Coefficients> identities = family_contact_triples(Family::O1);
    const LatticeCheck<DInterval> check = check_lattice(o1_basis(root.box[0], root.box[1], p), p, [&](const Coefficients& c) {
        return std::find(identities.begin(), identities.end(), c) != identities.end();
    });
    if (check.verdict != Outcome::refuted) return std::nullopt;
    Json verdict = lattice_verdict_json(check);
    verdict["verdict"] = "overlapping_at_point";
    verdict["at"] = rational_text(middle);
    return verdict;
}

}  // namespace

template <class Field>
Json family_lattice_check_certificate(const FamilyLattice<typename Field::Interval>& lattice,
                                      const LatticeCheck<typename Field::Interval>& check, const Rational& p,
                                      const Field& field, long digits) {
    if (check.verdict == Outcome::undecided) throw std::runtime_error("certificate: the lattice check is undecided");
    const std::string family = to_string(lattice.family);
    Json data = lattice_verdict_json(check);
    data["family"] = family;
    data["p"] = rational_text(p);
    data.update(family_definition_json(lattice.family));
    Json claim{{"kind", "family-lattice-check"}, {"data", data}};
    Json inputs{{"family", family}, {"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}};
    Json proof{{"kind", "family-lattice-check"},
               {"parameters", family_parameter_proof(lattice, field.rational(p))},
               {"lattice", lattice_enumeration_json(check)}};
    return certificate_document(certificate_head("check-lattice", field, digits), claim, inputs, proof);
}

Json audit_certificate(const AuditResult& result) {
    if (result.branch != AuditBranch::published) throw InputError("audit certificates cover the published lattice only");
    const Family family = result.family;
    // O1 and D14 are audited by continuation of their root from p = 1/2 (audit.cpp).
    const bool continued = !family_definition(family).continuation_start.empty();
    if (continued && result.range.lo != Rational(1, 2))
        throw InputError(std::string(family == Family::O1 ? "an " : "a ") + to_string(family) +
                         " audit certificate starts at p = 1/2 (the branch is followed from Minkowski's lattice)");
    const bool s6 = family == Family::S6;
    const DoubleField field;
    Json pieces = Json::array(), proofs = Json::array();
    bool linked = true;  // O1, D14: the continuation from p = 1/2 is unbroken up to this piece
    for (const AuditPiece& piece : result.pieces) {
        const Json p{{"lo", rational_text(piece.lo)}, {"hi", rational_text(piece.hi)}};
        const DInterval p_interval = hull(field.rational(piece.lo), field.rational(piece.hi));
        Json parameters(nullptr), lattice(nullptr), verdict;
        const bool certified = piece.lattice && piece.lattice->status == Outcome::proved;
        bool decided = certified && piece.check && piece.check->verdict != Outcome::undecided;
        const bool linked_before = linked;
        if (s6) {
            // The producer certifies only pieces on the chain from 9/10 (audit.cpp); the box is
            // proved about the piece's midpoint p0 (s6_piece).
            if (certified) {
                Rational p0 = (piece.lo + piece.hi) / 2;
                p0.canonicalize();
                const auto& search = piece.lattice->search.back();
                parameters = Json{{"kind", "krawczyk"}, {"status", "unique"}, {"p0", rational_text(p0)},
                                  {"box", box_json(search.piece)}, {"root", box_json(search.root)}};
            }
        } else if (continued) {
            if (certified)
                parameters = Json{{"kind", "krawczyk"}, {"status", "unique"}, {"box", box_json(piece.lattice->search.back().piece)}};
            // A piece after a break in the continuation from p = 1/2 cannot be decided.
            decided = decided && linked;
            linked = linked && certified;
        } else if (decided) {
            parameters = family_parameter_proof(*piece.lattice, p_interval);
        }
        std::optional<Json> at_point;
        if (!decided && family == Family::O1 && certified && linked_before && piece.outcome == "overlapping_at_point")
            at_point = o1_point_refutation(piece);
        if (decided) {
            verdict = lattice_verdict_json(*piece.check);
            lattice = lattice_enumeration_json(*piece.check);
        } else if (at_point) {
            verdict = *at_point;
        } else {
            verdict = Json{{"verdict", "undecided"}};
        }
        Json entry{{"p", p}};
        entry.update(verdict);
        pieces.push_back(entry);
        proofs.push_back(Json{{"parameters", parameters}, {"lattice", lattice}});
    }
    const Json range{{"lo", rational_text(result.range.lo)}, {"hi", rational_text(result.range.hi)}};
    Json data{{"family", to_string(family)}, {"lattice", "published"}, {"range", range}, {"pieces", pieces}};
    data.update(family_definition_json(family));
    Json claim{{"kind", "audit"}, {"data", data}};
    if (decided_pieces(claim["data"]) == 0) throw std::runtime_error("certificate: no piece of the audit is decided");
    Json inputs{{"family", to_string(family)}, {"range", range}};
    Json proof{{"kind", "audit"}, {"pieces", proofs}};
    if (s6) {
        // The anchor the audit's chain started from (audit_family), not a second point proof.
        const std::optional<S6Branch>& anchor = result.anchor;
        if (!anchor) throw std::runtime_error("certificate: the S6 audit result has no anchor");
        proof["anchor"] = Json{{"kind", "krawczyk"}, {"status", "unique"}, {"box", box_json(anchor->box)}, {"root", box_json(anchor->root)}};
    }
    return certificate_document(certificate_head("audit", field, 15), claim, inputs, proof);
}

std::size_t decided_pieces(const Json& data) {
    const Json& pieces = data.contains("claim") ? data["claim"]["data"]["pieces"] : data["pieces"];
    std::size_t decided = 0;
    for (const Json& piece : pieces) decided += piece["verdict"] != "undecided";
    return decided;
}

template Json family_lattice_check_certificate(const FamilyLattice<DInterval>&, const LatticeCheck<DInterval>&,
                                               const Rational&, const DoubleField&, long);
template Json family_lattice_check_certificate(const FamilyLattice<Ball>&, const LatticeCheck<Ball>&, const Rational&,
                                               const BallField&, long);

}  // namespace superpack
