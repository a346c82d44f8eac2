// Collisions of two moving, rotating, growing superballs for the event-driven molecular dynamics
// of sim/event_md.hpp (Donev, Torquato & Stillinger, J. Comput. Phys. 202, 737 and 765 (2005)):
// the time of first contact (conservative advancement), the contact point and normal, and the
// elastic response. Floating point only: nothing here is linked into a certificate.
//
// Units (kept throughout sim/collision and sim/event_md): every particle has mass 1; the initial
// temperature is kT = 1, so a velocity component has variance 1; the body is c + a(t) R(q) K with
// the common scale a(t) = a0 + G t. For spheres (p = 1) a is the radius, so the diameter grows at
// dD/dt = 2 G (DTS's growth rate "gamma" is dD/dt in these units, so gamma = 2 G). Angular
// velocities are in the space frame, in radians per unit time; the inertia tensor is isotropic
// (cubic symmetry), I = a^2 k(p) Id (mass 1), with k(p) = <x_1^2 + x_2^2> over K.
#pragma once
#include "superpack/sim/overlap.hpp"
#include "superpack/sim/quaternion.hpp"
#include "superpack/sim/superball_shape.hpp"
#include "superpack/sim/vector3.hpp"

namespace superpack::sim {

// k(p) = <x_1^2 + x_2^2> over K = 2 <x_1^2>: the moment of inertia of K (mass 1) about any axis
// through its centre, over a^2. 2/5 at p = 1, 2/3 in the cube limit, 1/5 at p = 1/2 (the
// octahedron). By tanh-sinh quadrature of the slices, <x_1^2> = int_0^1 x^2 (1 - x^q)^(2/q) dx /
// int_0^1 (1 - x^q)^(2/q) dx with q = 2p (a slice x_1 = x of K is the superdisk of radius
// (1 - x^q)^(1/q)), to about 1e-13; cached per p (thread-safe).
double inertia_factor(double p);

// A rigid body in free flight from the present (time 0): at time t its centre is center +
// t velocity and its orientation is the rotation by |omega| t about omega (space frame) after
// `orientation` (exact for constant omega: with the isotropic inertia tensor a free body keeps
// its omega; the event loop keeps omega constant while the bodies grow, too).
struct MovingBody {
    Vector3 center;
    Quaternion orientation;
    Vector3 velocity;
    Vector3 angular_velocity;
};

// The body at time t (centre and orientation moved; velocities are constant), the quaternion
// renormalized.
MovingBody advance(const MovingBody& body, double t);

struct ContactOptions {
    // Contact is reported when the distance bound falls below this many a(t) R_c and the bodies
    // approach at their nearest points.
    double tolerance = 1e-10;
    // Zeno guard: at most this many advancement steps per call.
    int max_iterations = 2000;
};

enum class ContactOutcome {
    contact,  // first contact at `time` (within the tolerance, approaching)
    none,     // no contact up to the horizon
    capped,   // the iteration cap stopped the run: no contact before `time`, undecided after
};

struct ContactPrediction {
    ContactOutcome outcome = ContactOutcome::none;
    // contact: the contact time; none: the horizon; capped: the time reached (a certain lower
    // bound on the contact time, if any).
    double time = 0;
    int iterations = 0;
    // The normal of the last separating plane found (from a towards b; zero if none), for the
    // caller's warm start of the same pair's next prediction.
    Vector3 normal{0, 0, 0};
};

// The distance of the two bodies now, at scale `scale`: for p = 1 exactly |c_b - c_a| - 2a (0
// if negative); otherwise a times GJK's lower bound at unit scale (sim/overlap.hpp: bodies
// c / a + R K), 0 when it judges them touching. `normal` (if given) receives the unit separating
// direction from a towards b.
double distance(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale, Vector3* normal = nullptr);
// The same with GJK's warm start and accuracy (sim/overlap.hpp): a lower bound on the distance
// that may be up to hint.relative_accuracy below it.
double distance(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale, Vector3* normal,
                const SeparationHint& hint);

// The time of first contact in [0, horizon] of bodies a and b moving from time 0 at scale
// a(t) = a0 + G t (G >= 0), by conservative advancement (Mirtich 1996): at time t the bound d(t)
// on their distance is computed, and since every point of a body moves at most at |v| +
// |omega| a R_c + G R_c (translation, rotation about the centre, growth of the point's offset
// a R y, |y| <= R_c), the distance shrinks at most at
//     w = |v_a - v_b| + (|omega_a| + |omega_b|) a_h R_c + 2 G R_c,
// a_h = a(horizon) >= a on the whole run (the rotation term is dropped at p = 1, a ball, which
// rotation does not move). Sharper and as rigorous, when d > 0 is the gap of a separating
// plane with normal n: that fixed plane keeps separating the bodies while its gap is positive,
// and the gap shrinks at most at w_n = max(0, -<n, v_b - v_a>) + (|omega_a x n| + |omega_b x n|)
// a_h R_c + 2 G R_c; the step uses w_n (w only when no plane is known, d = 0). So the bodies
// cannot meet before t + d(t) / w_n: each step
// t -> t + (d - m)/w_n, m = tolerance a R_c / 4, stays before the first contact with the bodies
// at least m apart, and a contact is never stepped over (every reported time is before the true
// one, and no contact is missed). The run stops when d < tolerance a R_c while the bodies
// approach at their nearest points (contact, with a gap between m and the tolerance), when t
// passes the horizon (none), or after max_iterations steps (capped, the Zeno case of grazing
// bodies, where the steps shrink geometrically without reaching the tolerance). While d is
// below the tolerance but the bodies separate (right after a collision), the step is
// max(d - m, m) / w_n. Between GJK runs (at most 16 steps apart, and always within twice the
// tolerance) the gap of the last GJK plane is used: two support values instead of a GJK run.
ContactPrediction first_contact(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double a0, double G,
                                double horizon, const ContactOptions& options = {});
// The same for md's fast loop, with the same guarantee: GJK starts from `hint.direction` (the
// pair's last normal) and, while the distance bound is above `accurate_below` tolerances, stops
// at `hint.relative_accuracy` (its gap is still a lower bound, so a step stays before the
// contact, only shorter); below that, and for the contact decision, GJK runs to convergence as
// in the reference. Fewer GJK steps per call; the reported contact time may differ from the
// reference's within the tolerance, as the advancement's steps differ.
ContactPrediction first_contact(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double a0, double G,
                                double horizon, const ContactOptions& options, const SeparationHint& hint);

// Bodies in contact now: the contact point (midway between the support points of the two bodies
// along the normal), the unit normal from a towards b, and the distance bound.
struct Contact {
    Vector3 point;
    Vector3 normal;
    double distance = 0;
};
Contact contact(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale);

// The velocity at which the gap between the bodies at the contact closes or opens: the normal
// component of (velocity of b's point) - (velocity of a's point), growth included (a point at
// offset x from the centre of a body of scale a moves with x G / a from growth). Positive:
// separating.
double normal_gap_rate(const MovingBody& a, const MovingBody& b, double scale, double G, const Contact& contact);

struct CollisionResponse {
    double impulse = 0;        // J: b receives J normal, a receives -J normal
    double energy_change = 0;  // translational + rotational kinetic energy after minus before
};

// The collision of frictionless rigid bodies of mass 1 and inertia scale^2 k Id at `contact`
// (their state at the contact time in a and b; only velocities and angular velocities change):
// an impulse J n along the normal. With u the rigid-body normal relative velocity at the contact
// point (without growth, u < 0 approaching) and g = G/a <n, x_a - x_b> >= 0 the rate at which
// growth closes the gap (x_a, x_b the contact point minus each centre), the rigid part becomes
// u' = -u + 2 g: at G = 0 the elastic collision (u reversed, kinetic energy and linear and
// angular momentum conserved); for growing bodies DTS's correction, so that the gap opens at
// u' - g = -(u - g) > 0 (the closing rate including growth is reversed) and the bodies separate
// at least at the growth rate (u' > g). That injects energy, which the event loop takes out by
// rescaling the velocities to kT = 1 now and then. J = (u' - u) / (2 + |x_a x n|^2 / I + |x_b x n|^2 / I).
CollisionResponse collide(double k, double scale, double G, const Contact& contact, MovingBody& a, MovingBody& b);

}  // namespace superpack::sim
