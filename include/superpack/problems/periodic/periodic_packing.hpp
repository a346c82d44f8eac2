// A periodic packing of N rotated convex superballs, proved: the certifying side of
// `superpack simulate` (NOTES.md 14). The configuration is exact: rational period vectors,
// rational centres and rational quaternions, whose rotation matrices R(q) = (...) / |q|^2 are
// exact and orthogonal. Two placed bodies c_i + R_i K and c_j + R_j K are disjoint in their
// interiors when a plane separates them: for a normal n,
//   h_K(R_i^T n) + h_K(R_j^T n) <= <n, c_j - c_i>,   h_K(u) = ||u||_r, 1/(2p) + 1/r = 1,
// which intervals decide. Every pair whose centres are closer than twice a proved circumradius
// bound, periodic images included, is enumerated exactly and given a normal: the guess of the
// caller (floating point may guess), or the centre difference itself when the guess does not
// face the right way. A pair the test cannot prove at the given scale needs the whole
// configuration scaled by s >= (h_i + h_j) / <n, d>; the smallest such s over all pairs (rounded
// up to a dyadic) is applied and everything proved again, so the result never depends on how
// good the guess was.
#pragma once
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "superpack/arith/exact.hpp"
#include "superpack/arith/interval.hpp"
#include "superpack/arith/outcome.hpp"
#include "superpack/geometry/lattice_basis.hpp"

namespace superpack {

using RationalVector3 = std::array<Rational, 3>;
using Shift = std::array<int, 3>;

struct PeriodicPacking {
    Rational p;
    Basis<Rational> cell;                              // rows: the period vectors
    std::vector<RationalVector3> centers;              // Cartesian
    std::vector<std::array<Rational, 4>> quaternions;  // (w, x, y, z), nonzero
};

// The pair (first, second) with second's image shifted by shift . cell, first <= second, and
// for first == second a lexicographically positive shift: the order the checker enumerates.
struct PairSeparation {
    std::size_t first = 0, second = 0;
    Shift shift{};
    RationalVector3 normal;
};

template <class I>
struct PeriodicCertificate {
    Outcome status = Outcome::undecided;  // proved: every pair is separated, a packing
    std::string reason;
    PeriodicPacking packing;    // the configuration proved (the input times `scale`)
    Rational scale = 1;         // 1 when the input itself was proved
    Rational radius;            // every R_i K lies in the ball of this radius about c_i
    std::vector<PairSeparation> pairs;
    Rational determinant;       // |det cell|, exact
    std::optional<I> phi;       // N V(p) / |det cell|, a packing density when proved
};

// The caller's guess of a separating normal (from first towards second) for a pair whose
// centre difference is about `difference`.
using NormalGuess = std::function<std::array<double, 3>(std::size_t first, std::size_t second, const std::array<double, 3>& difference)>;

// The limits of the certification, enforced: particles, and candidate shifts per pair.
constexpr std::size_t max_periodic_particles = 256;
constexpr long max_shifts_per_pair = 1000000;

// R(q) exactly.
Basis<Rational> rotation_of(const std::array<Rational, 4>& quaternion);

// x rounded to the nearest multiple of 2^-bits, exactly.
Rational dyadic_near(double x, int bits);

// Proves the packing (p >= 1/2); throws InputError for p < 1/2, a singular cell, a zero
// quaternion or more than max_periodic_particles particles.
PeriodicCertificate<DInterval> certify_periodic_packing(const PeriodicPacking& packing, const NormalGuess& guess, const DoubleField& field);
PeriodicCertificate<Ball> certify_periodic_packing(const PeriodicPacking& packing, const NormalGuess& guess, const BallField& field);

}  // namespace superpack
