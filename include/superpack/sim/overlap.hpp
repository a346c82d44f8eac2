// Do two placed superballs overlap, and how far apart are they? Floating point: the
// simulation's guess, which problems/ proves (or scales until it can) with intervals.
//
// Both tests run GJK (Gilbert, Johnson & Keerthi 1988; van den Bergen's formulation) on the
// Minkowski difference D = A - B, whose support map is s_A(n) - s_B(-n): the bodies meet iff
// 0 is in D, and their distance is the distance of 0 from D. Each step takes the support point
// w of D in the direction -v of the current nearest point v of a simplex of support points,
// and replaces the simplex by the least face of simplex + w nearest to 0. <v, w> / |v| is a
// lower bound on the distance (the gap of the plane with normal -v), |v| an upper bound; the
// run stops when they agree, when the simplex holds 0, or after an iteration cap.
#pragma once
#include "superpack/sim/superball_shape.hpp"
#include "superpack/sim/vector3.hpp"

namespace superpack::sim {

// A placed body: center + rotation K, `rotation` mapping body to space coordinates.
struct Placement {
    Vector3 center;
    Matrix3 rotation;
};

struct Separation {
    // The interiors meet: the distance is at most the contact tolerance below.
    bool overlapping;
    // Not overlapping: the gap of the plane with `normal`, min over b of <normal, y> minus
    // max over a of <normal, x>, a lower bound on the distance of the bodies that equals it
    // to about 1e-10 relative (or 1e-13 of the circumradius) when GJK converged; when the
    // bounding spheres are apart, |center difference| - 2 circumradius. Overlapping: 0.
    double distance;
    // Unit, from a towards b: <normal, x> <= <normal, y> for x in a and y in b, to rounding.
    // Overlapping: the normal of the best plane GJK tried (for bodies in near contact, close to
    // the contact normal: what a proof that scales them apart wants), or the unit center
    // difference (e_1 when the centers coincide) when GJK did not run.
    Vector3 normal;
};

// Bodies whose distance is at most this many circumradii count as overlapping: a pair
// judged apart is apart by a margin far above GJK's rounding errors (about 1e-15 here).
inline constexpr double contact_tolerance = 1e-12;

// The boolean test: stops as soon as a separating plane or a simplex around 0 is found.
bool overlapping(const SuperballShape& shape, const Placement& a, const Placement& b);
// The distance test: runs GJK to convergence. Agrees with `overlapping` except where the
// distance is within rounding of the contact tolerance.
Separation separation(const SuperballShape& shape, const Placement& a, const Placement& b);

// What a caller that has tested the same pair before can tell GJK (md's fast loop, which asks
// for the same pair's distance again and again as the bodies move a little):
struct SeparationHint {
    // A unit direction from a towards b (the normal of the last test), where GJK starts its
    // search instead of the centre difference; zero: none. Near the answer, fewer steps.
    Vector3 direction{0, 0, 0};
    // Stop when the gap of the best plane is within this fraction of GJK's upper bound on the
    // distance (at least the default 1e-10): the gap is then at least (1 - accuracy) times the
    // distance, and it is a lower bound whatever the accuracy, which is all that conservative
    // advancement needs far from contact.
    double relative_accuracy = 0;
};
Separation separation(const SuperballShape& shape, const Placement& a, const Placement& b, const SeparationHint& hint);

namespace detail {
// How a GJK run ended, for the tests: `converged` when the distance bounds met, `stalled` when
// rounding stopped the progress, `capped` at the iteration cap.
struct GjkTrace {
    int iterations = 0;
    bool converged = false, stalled = false, capped = false;
};
// Both tests above: stop_at_first_plane for `overlapping`.
Separation gjk(const SuperballShape& shape, const Placement& a, const Placement& b, bool stop_at_first_plane, GjkTrace* trace,
               const SeparationHint& hint = {});
}  // namespace detail

// A support point of a placed body: center + R s_K(R^T n).
Vector3 support_point(const SuperballShape& shape, const Placement& body, const Vector3& direction);
// Its support value <center, n> + h_K(R^T n).
double support_value(const SuperballShape& shape, const Placement& body, const Vector3& direction);

}  // namespace superpack::sim
