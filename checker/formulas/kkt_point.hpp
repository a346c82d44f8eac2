// The replay of a critical lattice: the KKT point (B, mu) of min det B subject to
// ||c_i B||_(2p) = 2 (equations_kkt.hpp), proved to exist and be unique in a stored box by
// Krawczyk. Shared by the claim kind local-optimum and by any family whose lattice is defined
// as such a KKT point (its basis at p is the B of the point).
#pragma once
#include <string>
#include <vector>

#include "checker/formulas/equations.hpp"
#include "checker/formulas/equations_kkt.hpp"

namespace superpack_checker {

struct KktPoint {
    Matrix3 basis;                  // the checker's tightened enclosure of B (rows)
    std::vector<Real> multipliers;  // of mu_1..mu_m, in the order of the contacts
    Box root;                       // the whole x = (b_00, ..., b_22, mu_1, ..., mu_m)
};

// `leaf` (at `path`) is a Krawczyk leaf of the certificate format (NOTES.md 8.1) {"kind":
// "krawczyk", "status": "unique", "box", "root"} over the 9 + m unknowns, m = contacts.size();
// p is a point or an interval (then the point is unique for every p in it). The checker replays
// Krawczyk on the box with its own KKT system, requires exactly one root there, and the stored
// root to hold its own tightened root box, which it returns. Rejects at path.box when the box
// has the wrong dimension or lets a contact coordinate reach 0 while 2p - 2 may be < 0 (the
// Jacobian is unbounded there: UnboundedPower), at `path` when Krawczyk proves nothing, at
// path.root[k] when the stored root misses the checker's. Requires p > 1/2 (the caller checks
// it on the exact p) and nonzero contact triples.
KktPoint replay_kkt_point(Context& context, const std::vector<Triple>& contacts, const Json& leaf, const std::string& path,
                          const Real& p);

}  // namespace superpack_checker
