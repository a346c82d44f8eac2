// The superball K = {x : |x1|^(2p) + |x2|^(2p) + |x3|^(2p) <= 1} in binary64, for the
// simulation's overlap tests: its gauge and its support map, the double counterparts of
// geometry/body.hpp's interval formulas. Only convex K (p >= 1/2): GJK (sim/overlap.hpp) needs
// a support map, and a support map sees only the convex hull.
//
// With q = 2p and the dual exponent r = q / (q - 1), Hoelder's inequality gives the support
// function h_K(n) = max over x in K of <n, x> = ||n||_r, attained at
// x_i = sign(n_i) |n_i|^(r-1) / ||n||_r^(r-1). Every power here is taken of |n_i| / max|n_j|,
// which lies in [0, 1]: the exponents reach 5 10^6 near p = 1/2 and 2 10^6 near the cube
// (p = 10^6), where |n_i| itself would overflow or underflow.
#pragma once
#include "superpack/sim/vector3.hpp"

namespace superpack::sim {

class SuperballShape {
public:
    // Throws std::invalid_argument unless p is finite and p >= 1/2.
    explicit SuperballShape(double p);
    double p() const { return p_; }

    // sum |x_i|^(2p): below 1 inside K, 1 on its boundary.
    double gauge_power(const Vector3& x) const;
    // ||x||_(2p), the least t >= 0 with x in tK, scaled so that it neither underflows nor
    // overflows at large p (where gauge_power of a point well inside K is 0 in binary64).
    double gauge(const Vector3& x) const;

    // A point of K maximising <direction, x> (0 for direction 0). At p = 1/2, the octahedron,
    // the vertex sign(n_k) e_k of the first largest |n_k|; it is odd in `direction`, as K is
    // symmetric, which GJK relies on.
    Vector3 support_point(const Vector3& direction) const;
    // h_K(direction) = ||direction||_r (max |n_i| at p = 1/2).
    double support_value(const Vector3& direction) const;

    // max |x| over K: 1 for p <= 1 (K lies in the unit ball and contains e_1), and
    // 3^(1/2 - 1/(2p)) for p >= 1, at the diagonal point (1, 1, 1) 3^(-1/(2p)).
    double circumradius() const { return circumradius_; }
    // max r with the ball of radius r in K: 3^(1/2 - 1/(2p)) for p <= 1 (the ball reaches the
    // diagonal point) and 1 for p >= 1 (it reaches e_1). Bodies whose centers are closer than
    // twice this overlap without a GJK run.
    double inradius() const { return inradius_; }

private:
    double p_;
    double q_;                  // 2p
    double inverse_q_;          // 1/q
    double r_minus_one_;        // 1 / (q - 1), exactly rather than r - 1 (which would cancel near the cube)
    double r_;                  // q / (q - 1); infinite at p = 1/2
    double inverse_r_;          // (q - 1) / q, computed so rather than as 1 - 1/q (which cancels near p = 1/2)
    double circumradius_;
    double inradius_;
};

}  // namespace superpack::sim
