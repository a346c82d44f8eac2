// S6, superpack's own family on p*_o < p < 1 (issue 12, item 4; NOTES.md 4.2): the lattice at p
// is the KKT point of min det B subject to ||c_i B||_(2p) = 2 for Minkowski's six pairs
// (configuration A3: b1, b2, b3, b2 - b3, b3 - b1, b1 - b2), the one on the branch through a
// stored seed at p = 9/10. This file holds the definition (the triples and the seed) and the
// floating-point continuation that guesses the point at p; the proof is Krawczyk on
// kkt_equations (local_optimality.hpp), in enclose_family (families.hpp).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "superpack/geometry/lattice.hpp"
#include "superpack/problems/guess/lattice_search.hpp"

namespace superpack {

// The six triples in S6's canonical basis, one per +-pair: b1, b2, b3, b2 - b3, b1 - b3 (that
// is -(b3 - b1)) and b1 - b2, in the order of the multipliers mu1..mu6.
const std::vector<Coefficients>& s6_contact_triples();

// The seed's p, 9/10: where the stored guess of the KKT point lies.
Rational s6_seed_p();

// The KKT point at p in floating point, followed by Newton (kkt_point, from the basis and the
// multipliers of the point before) from the seed at 9/10 in steps of p of at most 1/400 (halved where Newton fails, down to 2^-24). A guess only. Nothing,
// with the reason in `failure`, when the continuation loses the point.
std::optional<KktPoint> s6_guess(double p, std::string& failure);

}  // namespace superpack
