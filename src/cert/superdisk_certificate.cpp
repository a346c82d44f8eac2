#include "superpack/cert/superdisk_certificate.hpp"

#include <stdexcept>

#include "superpack/cert/certificate_partition.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/arith/exact.hpp"

namespace superpack {

namespace {

// The mathematical premise the checker does not replay (it replays the computation only).
const char* const premise_text =
    "Premise (not replayed): for a centrally symmetric convex disk K the densest packing of translates is a "
    "lattice packing (L. Fejes Toth 1950; C. A. Rogers 1951), of density area(K) / Delta(2K) = area(K) / "
    "(4 Delta(K)); and Delta(K) = min over u in bd K of det(u, v(u)), where v(u) is the point of bd K with "
    "v - u in bd K and det(u, v) > 0, because every lattice with a basis u, v such that u, v, v - u lie on bd K "
    "is K-admissible and some critical lattice has such a basis (Reinhardt 1934, Mahler 1947; Cassels, An "
    "Introduction to the Geometry of Numbers, ch. V): the inscribed affinely regular hexagon +-u, +-v, "
    "+-(v - u). The superdisk |x|^(2p) + |y|^(2p) <= 1 is convex for p >= 1/2 and strictly convex for "
    "p > 1/2, so v(u) is unique.";

const char* const parameter_text =
    "u(t) = (x, t x), x = (1 + t^q)^(-1/q), q = 2p, t in [0, 1]; v(t) = (a, b) solves |a|^q + |b|^q = 1 and "
    "|a - x|^q + |b - t x|^q = 1 with D(t) = det(u, v) = x b - t x a > 0 (the other solution u - v has "
    "det < 0); the packing lattice has basis 2u, 2v and determinant 4 D(t)";

const char* const symmetry_text =
    "t in [0, 1] suffices: D depends on the lattice only, so D(u) = D(-u) = D(v) = D(v - u), and every element "
    "g of the symmetry group of the square maps K to K and an admissible hexagon lattice to one of the same "
    "|det| (a reflection reverses the orientation; the next vertex is then g(u - v)), so D(g u) = D(u); every "
    "direction of u is the image of one with polar angle in [0, pi/4], i.e. of some u(t), t in [0, 1] "
    "(NOTES.md 7.2). Minimisers in t are therefore only those in the first octant; their images under the "
    "group (and the other two vertices of each optimal hexagon) are the other minimising u";

const char* const exclusion_text =
    "p = 1/2 (the square, which tiles: phi = 1, no branch and bound) and p < 1/2 (not convex) have no "
    "certificate of this kind";

template <class I>
Json lattice_proof_json(const HexagonLattice<I>& lattice) {
    const bool axis = contains(field_of(lattice.t).integer(0), lattice.t);
    return Json{{"search_box", box_json(lattice.search_box)},
                {"reason", axis ? "closed form at t = 0: the contact system gives |a| = |a - 1|, so v = (1/2, (1 - 2^-q)^(1/q)) "
                                  "(the search box is that point)"
                                : "Krawczyk: K(X) in the interior of X for the contact system at the lattice's t "
                                  "(claim.data.lattices), and det(u, v) > 0"}};
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

    const DecimalEnclosure phi_text = to_decimal(report.optimal_phi, 17);
    std::string attained_text = attained.empty() ? "by no lattice checked by name (Lambda0, Lambda1)"
                                                 : "by " + report.attained_by;
    Json claim{{"kind", "superdisk-optimum"},
               {"text", std::string("The densest lattice packing of the superdisk |x|^(2p) + |y|^(2p) <= 1 at p = ") +
                            rational_text(p) + " has density phi = area / Delta(2K) in [" + phi_text.lo + ", " +
                            phi_text.hi + "] (exact endpoints in data.optimal_phi; Delta(2K) in data.optimal_determinant), "
                            "attained within that enclosure " + attained_text +
                            " (determinant 4 D within the enclosure of Delta(2K), t in data.argmin_t), and every "
                            "minimiser t in [0, 1] of D(t) lies in data.argmin_t. Premise, not replayed (proof.premise): the "
                            "densest packing of translates of a centrally symmetric convex disk is a lattice packing (Fejes "
                            "Toth 1950, Rogers 1951), and Delta(K) = min det(u, v) over the inscribed affinely regular "
                            "hexagons u, v, v - u on bd K (Reinhardt 1934, Mahler 1947; Cassels, Geometry of Numbers, ch. V)"},
               {"data", Json{{"p", rational_text(p)},
                             {"area", exact_interval_json(report.area)},
                             {"optimal_determinant", exact_interval_json(report.optimal_determinant)},
                             {"optimal_phi", exact_interval_json(report.optimal_phi)},
                             {"argmin_t", argmin},
                             {"attained_by", attained},
                             {"lattices", lattices_claim}}}};
    Json inputs{{"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}};
    Json proof{{"kind", "superdisk-branch-and-bound"},
               {"premise", premise_text},
               {"parameter", parameter_text},
               {"symmetry", symmetry_text},
               {"excluded", exclusion_text},
               {"text", "The pieces cover [0, 1]. On each, Krawczyk with t the whole piece proves one v(t) in the search "
                        "box for every t in it (at the point t = 0, v = (1/2, (1 - 2^-q)^(1/q)) in closed form). A piece is "
                        "monotone (D' of one sign, by implicit differentiation: its lower bound is D at one end), bounded "
                        "(its lower bound is the naive enclosure of D, or that intersected with the mean-value form "
                        "D(m) + D'(T)(T - m); or, method a_priori, for a piece with no Krawczyk proof, "
                        "x y1 - t x max(0, min(x/2, x - (1 - 2^-q - (y1 - t x)^q)^(1/q))) with y1 = (1 - 2^-q)^(1/q), "
                        "a lower bound of det(u, v) for every solution v with det(u, v) > 0 at every t of the piece), "
                        "or discarded (its lower bound exceeds D of the witness lattice). min D lies "
                        "between the least lower bound of the pieces not discarded and D of the witness; every minimiser "
                        "lies in a piece not discarded."},
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
