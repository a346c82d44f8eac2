// The gauge of the difference body D = K - K of the superball K = {sum |x_i|^q <= 1}, q = 2p, in
// floating point: K + v meets the interior of K iff ||v||_D < 1, so a lattice packs translates of
// K iff 2 ||v||_D >= 2 for every nonzero lattice vector v (for p >= 1/2, D = 2K and 2 ||v||_D is
// the 2p-norm). A guess for the search (problems/guess/lattice_search.hpp); certified overlap tests are
// geometry/star_overlap.hpp.
//
// For q < 1 the minimum over x of max(g(x), g(x - v)), m(v) = ||v||_D^q, is attained where every
// x_i but at most one equals 0 or v_i (NOTES.md 13.4): clipping x_i into the segment between 0 and
// v_i lowers both terms, and along the trade-off of two interior coordinates that keeps g(x) fixed,
// g(x - v) is concave (b = (|v_i| - a^(1/q))^q is concave in a), so it is least at an end. So m(v)
// is the least over the interior coordinate k and the split of the others into S (x_i = v_i) and
// T (x_i = 0) of the level c at which (c - A_S)^(1/q) + (c - A_T)^(1/q) = |v_k|, A_S the sum of
// |v_i|^q over S.
#pragma once
#include <array>

namespace superpack {

// ||v||_D for p > 0: between max |v_i| / 2 and half the 2p-gauge of v, since 2K lies in D and D in
// [-2, 2]^3.
double difference_gauge(const std::array<double, 3>& v, double p);

}  // namespace superpack
