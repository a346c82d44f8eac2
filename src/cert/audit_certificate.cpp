#include "superpack/cert/audit_certificate.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "superpack/arith/decimal.hpp"
#include "superpack/cert/certificate_partition.hpp"
#include "superpack/cert/family_certificate.hpp"

namespace superpack {

namespace {

bool canonical(const Coefficients& c) {
    for (long x : c)
        if (x != 0) return x > 0;
    return false;
}

// The verdict as the claim states it: {"verdict", "contacts", "contact_vectors"} for a packing,
// {"verdict", "witness": {"coefficients", "norm"}} for an overlap.
template <class I>
Json verdict_json(const LatticeCheck<I>& check) {
    if (check.verdict == Verdict::admissible) {
        Json vectors = Json::array();
        for (const auto& c : check.contact_vectors) vectors.push_back(coefficients_json(c));
        return Json{{"verdict", "packing"}, {"contacts", check.contacts()}, {"contact_vectors", vectors}};
    }
    if (check.verdict == Verdict::overlapping)
        return Json{{"verdict", "overlapping"},
                    {"witness", Json{{"coefficients", coefficients_json(check.witness->coefficients)},
                                     {"norm", exact_interval_json(check.witness->norm)}}}};
    throw std::runtime_error("certificate: the lattice check is undecided");
}

// The enumeration step of a packing verdict: the coefficient bound and the contacts (one per
// +-pair); the checker enumerates the box on its own basis. Nothing for an overlap (the
// witness in the claim is its own proof).
template <class I>
Json enumeration_json(const LatticeCheck<I>& check) {
    if (check.verdict != Verdict::admissible) return Json(nullptr);
    Json contacts = Json::array();
    for (const auto& c : check.contact_vectors)
        if (canonical(c)) contacts.push_back(Json{{"coefficients", coefficients_json(c)}});
    return Json{{"kind", "enumeration"},
                {"text", "every v = a e1 + b e2 + c e3 with ||v||_(2p) <= 2 has |a_i| <= floor(2 ||e_j x e_k||_1 / |det|) "
                         "(Cramer and Hoelder); every triple of that box has a coordinate beyond 2, a norm above 2, or "
                         "is a contact: its halved coordinates are, up to sign and order, the terms of one of the "
                         "family's equations (Eqs. 2, 5, 9, 12, or t^(2p) = 1/2, 3 l^(2p) = 1), so its norm is exactly 2"},
                {"coefficient_bound", coefficients_json(check.coefficient_bound)},
                {"contacts", contacts}};
}

// An exact piece end for people: "0.5", or "1216766151/2392000000 (~0.50868150125)".
std::string end_text(const Rational& x) {
    const std::string exact = decimal_or_fraction_text(x);
    if (exact.find('/') == std::string::npos) return exact;
    return exact + " (~" + to_fixed(DoubleField{}.rational(x), 11).lo + ")";
}

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
    if (check.verdict != Verdict::overlapping) return std::nullopt;
    Json verdict = verdict_json(check);
    verdict["verdict"] = "overlapping_at_point";
    verdict["at"] = rational_text(middle);
    verdict["reason"] = "the lattice overlaps at the one point p = at; the rest of the piece is undecided (" + piece.reason + ")";
    return verdict;
}

std::string triple_text(const Coefficients& c) {
    return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ")";
}

const char* lattice_words(Family family) {
    switch (family) {
        case Family::C0: return "the C0 lattice (Eq. 1, s the smallest positive root of Eq. 2)";
        case Family::C1: return "the C1 lattice (Eq. 8, s the smallest positive root of Eq. 9)";
        case Family::O0: return "the O0 lattice (Eq. 5)";
        case Family::O1: return "the O1 lattice (Eq. 11, (q, s) the root of Eq. 12 with q >= 0 and the larger s)";
    }
    return "";
}

}  // namespace

template <class Field>
Json family_lattice_check_certificate(const FamilyLattice<typename Field::Interval>& lattice,
                                      const LatticeCheck<typename Field::Interval>& check, const Rational& p,
                                      const Field& field, long digits) {
    const std::string family = to_string(lattice.family);
    Json data = verdict_json(check);
    data["family"] = family;
    data["p"] = rational_text(p);
    std::string text = std::string("At p = ") + rational_text(p) + ", " + lattice_words(lattice.family);
    if (check.verdict == Verdict::admissible)
        text += " is a packing of the superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1 with " + std::to_string(check.contacts()) +
                " contacts (every nonzero lattice vector has 2p-norm >= 2, with equality exactly for the contact vectors)";
    else
        text += " is not a packing: the lattice vector with coefficients " + triple_text(check.witness->coefficients) +
                " has 2p-norm < 2";
    Json claim{{"kind", "family-lattice-check"}, {"text", text}, {"data", data}};
    Json inputs{{"family", family}, {"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}};
    Json proof{{"kind", "family-lattice-check"},
               {"text", "the parameters are proved as in a family-lattice certificate; then the enumeration over the "
                        "basis built from them decides every lattice vector of norm <= 2"},
               {"parameters", family_parameter_proof(lattice, field.rational(p))},
               {"lattice", enumeration_json(check)}};
    return certificate_document(certificate_head("check-lattice", field, digits), claim, inputs, proof);
}

Json audit_certificate(const AuditResult& result) {
    if (result.branch != AuditBranch::published) throw InputError("audit certificates cover the published lattice only");
    const Family family = result.family;
    if (family == Family::O1 && result.range.lo != Rational(1, 2))
        throw InputError("an O1 audit certificate starts at p = 1/2 (the branch is followed from Minkowski's lattice)");
    const DoubleField field;
    Json pieces = Json::array(), proofs = Json::array();
    bool linked = true;  // O1: the continuation from p = 1/2 is unbroken up to this piece
    struct Range {
        Rational lo, hi;
        std::string verdict;
    };
    std::vector<Range> summary;
    for (const AuditPiece& piece : result.pieces) {
        const Json p{{"lo", rational_text(piece.lo)}, {"hi", rational_text(piece.hi)}};
        const DInterval p_interval = hull(field.rational(piece.lo), field.rational(piece.hi));
        Json parameters(nullptr), lattice(nullptr), verdict;
        const bool certified = piece.lattice && piece.lattice->status == FamilyStatus::certified;
        bool decided = certified && piece.check && piece.check->verdict != Verdict::undecided;
        std::string reason = piece.reason;
        const bool linked_before = linked;
        if (family == Family::O1) {
            if (certified)
                parameters = Json{{"kind", "krawczyk"},
                                  {"status", "unique"},
                                  {"box", box_json(piece.lattice->search.back().piece)},
                                  {"reason", "K(X) in the interior of X for every p of the piece; the box of the "
                                             "previous piece holds this root at the shared end"}};
            if (decided && !linked) {
                decided = false;
                reason = "the continuation of the branch from p = 1/2 broke on an earlier piece";
            }
            linked = linked && certified;
        } else if (decided) {
            parameters = family_parameter_proof(*piece.lattice, p_interval);
        }
        std::optional<Json> at_point;
        if (!decided && family == Family::O1 && certified && linked_before && piece.outcome == "overlapping_at_point")
            at_point = o1_point_refutation(piece);
        if (decided) {
            verdict = verdict_json(*piece.check);
            lattice = enumeration_json(*piece.check);
        } else if (at_point) {
            verdict = *at_point;
        } else {
            if (piece.outcome == "overlapping_at_point")
                reason += " (the audit's point refutation is not part of this certificate)";
            verdict = Json{{"verdict", "undecided"}, {"reason", reason}};
        }
        Json entry{{"p", p}};
        entry.update(verdict);
        pieces.push_back(entry);
        proofs.push_back(Json{{"parameters", parameters}, {"lattice", lattice}});
        std::string words = entry["verdict"].get<std::string>();
        if (words == "packing") words += " with " + std::to_string(piece.check->contacts()) + " contacts";
        if (words == "overlapping") words += " (witness " + triple_text(piece.check->witness->coefficients) + ")";
        if (words == "overlapping_at_point") words = "undecided, but overlapping at one certified point per piece";
        if (!summary.empty() && summary.back().verdict == words && summary.back().hi == piece.lo)
            summary.back().hi = piece.hi;
        else
            summary.push_back({piece.lo, piece.hi, words});
    }
    std::string text = "For every p in each piece [lo, hi] of data.pieces (exact rational ends; the pieces cover [" +
                       end_text(result.range.lo) + ", " + end_text(result.range.hi) + "] without gaps), " +
                       (family == Family::O1 ? std::string("the O1 lattice (Eq. 11, (q, s) on the root branch of Eq. 12 through "
                                                           "Minkowski's (1/6, 2/3) at p = 1/2)")
                                             : std::string(lattice_words(family))) +
                       " has the verdict stated for the piece: a packing with the stated contacts, "
                       "or not a packing (the witness vector has 2p-norm < 2). A piece marked overlapping_at_point is "
                       "not a packing at the one point p = at of the piece (witness) and proves nothing about its other "
                       "p. Pieces marked undecided are listed with their reason and prove nothing.";
    if (family == Family::O1)
        text += " The branch is followed by continuation: a Krawczyk box per piece, each holding the root of the next "
                "piece at their shared end; a piece without a box breaks the chain.";
    text += " The verdicts, merged:";
    for (const Range& range : summary)
        text += " [" + end_text(range.lo) + ", " + end_text(range.hi) + "] " + range.verdict + ";";
    text.back() = '.';
    const Json range{{"lo", rational_text(result.range.lo)}, {"hi", rational_text(result.range.hi)}};
    Json claim{{"kind", "audit"},
               {"text", text},
               {"data", Json{{"family", to_string(family)}, {"lattice", "published"}, {"range", range}, {"pieces", pieces}}}};
    if (decided_pieces(claim["data"]) == 0) throw std::runtime_error("certificate: no piece of the audit is decided");
    Json inputs{{"family", to_string(family)}, {"range", range}, {"range_note", result.range.note}};
    Json proof{{"kind", "audit"},
               {"text", "per piece (same order as the claim): the proof of the family's parameters for every p of the "
                        "piece (p an interval), and for a packing the enumeration bound and the contacts"},
               {"pieces", proofs}};
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
