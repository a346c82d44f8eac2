// A floating-point search for dense lattice packings of the superball at p: guesses only. Every
// lattice it returns is certified or rejected by problems/best/best.hpp, and a proof never depends on
// how good the guess was (NOTES.md, "Densest lattice search").
//
// A lattice with basis rows B packs translates of the superball K iff every nonzero lattice
// vector has packing norm >= 2 (the 2p-norm for p >= 1/2, twice the gauge of K - K below);
// scaled so that its shortest vector has norm 2 it has density V(p) / |det B|. The search
// minimises the scale-free F(B) = log|det B| - 3 log(lambda(B) / 2), lambda the shortest packing
// norm, from given and random starts, by a pattern search, then (p >= 1/2) polishes each end point
// by Newton's method on the KKT system of min |det B| subject to ||c B||_(2p) = 2 for the
// near-shortest coefficient vectors c.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "superpack/geometry/lattice_basis.hpp"

namespace superpack {

using DoubleBasis = Basis<double>;

struct SearchStart {
    std::string name;  // where it comes from: a family, "random 3", ...
    DoubleBasis basis;
};

struct SearchOptions {
    unsigned seed = 1;       // random starts and directions (deterministic for a seed)
    int random_starts = 16;  // besides the given starts
    int perturbed_starts = 2;  // random perturbations of each given start
};

struct SearchCandidate {
    std::string start;    // the start it was found from
    DoubleBasis basis;    // LLL-like reduced, det > 0, shortest vector of norm 2 (to rounding)
    double density = 0;   // V(p) / |det B| in floating point
    // The coefficient vectors (one per +-pair, in `basis`) whose norm is within 1e-9 of the
    // shortest: the contacts of the critical lattice the candidate approximates.
    std::vector<std::array<long, 3>> near_contacts;
};

struct SearchResult {
    std::vector<SearchCandidate> candidates;  // one per start but those too skewed to enumerate (below 1/2), densest first
    long evaluations = 0;                     // of F
    double seconds = 0;                       // wall time of the search
};

// p > 0 as a double, volume V(p) as a double (only for the reported float density).
SearchResult search_dense_lattices(double p, double volume, const std::vector<SearchStart>& starts,
                                   const SearchOptions& options);

// A KKT point of min det B subject to ||c_i B||_(2p) = 2 for the `active` triples (at most
// nine), found by Newton's method from b: its basis and multipliers, all positive; nothing
// when Newton did not converge, a multiplier is not positive, or another vector got shorter.
struct KktPoint {
    DoubleBasis basis{};
    std::vector<double> multipliers;
};
std::optional<KktPoint> kkt_point(const DoubleBasis& b, double p, const std::vector<std::array<long, 3>>& active);
// The same from a basis and multipliers (one per triple), e.g. the point at a nearby p.
std::optional<KktPoint> kkt_point(const KktPoint& start, double p, const std::vector<std::array<long, 3>>& active);

// The shortest packing norm, and the norm of one vector: the packing norm is the 2p-norm for
// p >= 1/2 and twice the gauge of K - K below (problems/guess/difference_gauge.hpp), so that a lattice
// packs K iff all its vectors have it >= 2. For p >= 1/2 over the vectors c B with |c_i| <= 2 (B
// reduced); below, over every vector with max |v_i| under the shortest of those, or 0 when that
// enumeration would take over 10^5 coefficient pairs (a basis the search then discards).
double shortest_norm(const DoubleBasis& basis, double p);
double packing_norm(const std::array<double, 3>& v, double p);
double norm_2p(const std::array<double, 3>& v, double p);

}  // namespace superpack
