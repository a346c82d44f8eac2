#include "superpack/cert/superdisk_certificate.hpp"

#include <stdexcept>

#include "superpack/arith/decimal.hpp"
#include "superpack/arith/exact.hpp"
#include "superpack/cert/certificate_partition.hpp"

namespace superpack {

namespace {

template <class I>
Json lattice_proof_json(const HexagonLattice<I>& lattice) {
    return Json{{"search_box", box_json(lattice.search_box)}};
}

template <class I>
Json lattice_claim_json(const HexagonLattice<I>& lattice) {
    return Json{{"t", exact_interval_json(lattice.t)},
                {"determinant", exact_interval_json(lattice.determinant)},
                {"phi", exact_interval_json(lattice.phi)}};
}

template <class I>
Json piece_json(const HexagonPiece<I>& piece) {
    if (piece.verdict == PieceVerdict::undecided) throw std::runtime_error("certificate: an undecided piece");
    Json entry{{"t", exact_interval_json(piece.t)},
               {"verdict", to_string(piece.verdict)},
               {"method", to_string(piece.method)},
               {"search_box", box_json(piece.search_box)},
               {"lower_bound", exact_interval_json(lower_point(piece.lower_bound))}};
    if (piece.method == LowerBoundMethod::naive_and_mean_value) entry["center"] = exact_interval_json(piece.center);
    return entry;
}

}  // namespace

template <class Field>
Json superdisk_certificate(const SuperdiskReport<typename Field::Interval>& report, const Rational& p,
                           const Field& field, long digits) {
    if (report.status != OptimumStatus::certified)
        throw std::runtime_error("certificate: the superdisk optimum is not certified at this p");
    if (report.tiling || p <= Rational(1, 2))
        throw std::runtime_error("certificate: p = 1/2 (tiling) and p < 1/2 have no superdisk-optimum certificate");
    if (report.optimal_lattice.status != RootStatus::unique)
        throw std::runtime_error("certificate: no certified witness lattice");

    Json lattices_claim = Json::object(), lattices_proof = Json::object();
    for (const auto& [name, lattice] : {std::pair{"Lambda0", &report.lambda0}, std::pair{"Lambda1", &report.lambda1}}) {
        if (lattice->status != RootStatus::unique) continue;
        lattices_claim[name] = lattice_claim_json(*lattice);
        lattices_proof[name] = lattice_proof_json(*lattice);
    }
    Json attained = Json::array();
    if (report.attained_by == "Lambda0 and Lambda1") attained = Json::array({"Lambda0", "Lambda1"});
    else if (report.attained_by == "Lambda0" || report.attained_by == "Lambda1") attained.push_back(report.attained_by);
    Json argmin = Json::array();
    for (const auto& component : report.argmin_t) argmin.push_back(exact_interval_json(component));
    Json pieces = Json::array();
    for (const auto& piece : report.pieces) pieces.push_back(piece_json(piece));

    // The premise (Fejes Toth, Reinhardt-Mahler) and the symmetry reduction are stated in the
    // checker's sentence (NOTES.md 7.1-7.2).
    Json claim{{"kind", "superdisk-optimum"},
               {"data", Json{{"p", rational_text(p)},
                             {"area", exact_interval_json(report.area)},
                             {"optimal_determinant", exact_interval_json(report.optimal_determinant)},
                             {"optimal_phi", exact_interval_json(report.optimal_phi)},
                             {"argmin_t", argmin},
                             {"attained_by", attained},
                             {"lattices", lattices_claim}}}};
    Json inputs{{"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}};
    Json proof{{"kind", "superdisk-branch-and-bound"},
               {"witness", Json{{"t", exact_interval_json(report.optimal_lattice.t)},
                                {"search_box", box_json(report.optimal_lattice.search_box)},
                                {"determinant", exact_interval_json(report.optimal_lattice.determinant)}}},
               {"lattices", lattices_proof},
               {"pieces", pieces}};
    return certificate_document(certificate_head("superdisk", field, digits), claim, inputs, proof);
}

template Json superdisk_certificate(const SuperdiskReport<DInterval>&, const Rational&, const DoubleField&, long);
template Json superdisk_certificate(const SuperdiskReport<Ball>&, const Rational&, const BallField&, long);

}  // namespace superpack
