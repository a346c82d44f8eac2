#include "superpack/sim/collision.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

namespace superpack::sim {

// The contact of bodies whose GJK normal n and distance d are known.
Contact contact_along(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale, const Vector3& n, double d);

namespace {

// int_0^1 x^m (1 - x^q)^(2/q) dx by tanh-sinh quadrature: x = (1 + tanh(pi/2 sinh s)) / 2, step
// 2^-6 over |s| <= 3.5 (beyond, the weights are below 1e-22). The end x = 1, where the integrand
// has the singularity (1 - x)^(2/q), is where the nodes crowd; 1 - x is taken from the node's own
// formula, not by cancellation, and 1 - x^q = -expm1(q log1p(-(1 - x))).
double slice_moment(double q, int m) {
    const double h = 0x1p-6;
    double sum = 0;
    for (int i = -224; i <= 224; ++i) {
        const double s = i * h;
        const double u = M_PI / 2 * std::sinh(s);
        const double e = std::exp(-2 * std::fabs(u));  // in (0, 1]
        // x and 1 - x, each without cancellation.
        const double small = e / (1 + e), large = 1 / (1 + e);
        const double x = u >= 0 ? large : small, complement = u >= 0 ? small : large;
        const double weight = M_PI / 2 * std::cosh(s) * 2 * e / ((1 + e) * (1 + e));  // dx/ds = (pi/2) cosh s / (2 cosh^2 u)
        const double remaining = -std::expm1(q * std::log1p(-complement));     // 1 - x^q
        sum += weight * std::pow(x, m) * std::pow(remaining, 2 / q);
    }
    return h * sum;
}

double compute_inertia_factor(double p) {
    const double q = 2 * p;
    return 2 * slice_moment(q, 2) / slice_moment(q, 0);
}

Vector3 unit(const Vector3& v) {
    const double length = norm(v);
    if (!(length > 0) || !std::isfinite(length)) return {1, 0, 0};
    return (1 / length) * v;
}

// The support point of c + scale R K in direction n.
Vector3 scaled_support(const SuperballShape& shape, const Vector3& center, const Matrix3& rotation, double scale, const Vector3& n) {
    return center + scale * apply(rotation, shape.support_point(apply_transpose(rotation, n)));
}

// The gap min over b of <n, y> - max over a of <n, x> of bodies at `scale` (negative: the
// plane does not separate them).
double plane_gap(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale, const Vector3& n) {
    const double top_a = dot(a.center, n) + scale * shape.support_value(apply_transpose(rotation_matrix(a.orientation), n));
    const double bottom_b = dot(b.center, n) - scale * shape.support_value(apply_transpose(rotation_matrix(b.orientation), n));
    return bottom_b - top_a;
}

double kinetic_energy(const MovingBody& body, double inertia) {
    return 0.5 * dot(body.velocity, body.velocity) + 0.5 * inertia * dot(body.angular_velocity, body.angular_velocity);
}

}  // namespace

double inertia_factor(double p) {
    if (!std::isfinite(p) || !(p >= 0.5)) throw std::invalid_argument("inertia_factor: needs a finite p >= 1/2");
    static std::mutex mutex;
    static std::map<double, double> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    const auto found = cache.find(p);
    if (found != cache.end()) return found->second;
    const double k = compute_inertia_factor(p);
    cache.emplace(p, k);
    return k;
}

MovingBody advance(const MovingBody& body, double t) {
    MovingBody moved = body;
    moved.center = body.center + t * body.velocity;
    const double speed = norm(body.angular_velocity);
    if (speed > 0 && t != 0)
        moved.orientation = normalized(multiply(axis_angle((1 / speed) * body.angular_velocity, speed * t), body.orientation));
    return moved;
}

double distance(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale, Vector3* normal) {
    return distance(shape, a, b, scale, normal, SeparationHint{});
}

double distance(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale, Vector3* normal,
                const SeparationHint& hint) {
    const Vector3 delta = b.center - a.center;
    if (shape.p() == 1) {
        if (normal) *normal = unit(delta);
        return std::max(0.0, norm(delta) - 2 * scale);
    }
    const Placement first{{0, 0, 0}, rotation_matrix(a.orientation)};
    const Placement second{(1 / scale) * delta, rotation_matrix(b.orientation)};
    const Separation separated = separation(shape, first, second, hint);
    if (normal) *normal = separated.normal;
    return separated.overlapping ? 0.0 : scale * separated.distance;
}

Contact contact(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale) {
    Vector3 n;
    const double d = distance(shape, a, b, scale, &n);
    return contact_along(shape, a, b, scale, n, d);
}

Contact contact_along(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale, const Vector3& n, double d) {
    Contact result;
    result.distance = d;
    result.normal = n;
    const Vector3 on_a = scaled_support(shape, a.center, rotation_matrix(a.orientation), scale, n);
    const Vector3 on_b = scaled_support(shape, b.center, rotation_matrix(b.orientation), scale, -n);
    result.point = 0.5 * (on_a + on_b);
    return result;
}

double normal_gap_rate(const MovingBody& a, const MovingBody& b, double scale, double G, const Contact& contact) {
    const Vector3 xa = contact.point - a.center, xb = contact.point - b.center;
    const Vector3 velocity_a = a.velocity + cross(a.angular_velocity, xa) + (G / scale) * xa;
    const Vector3 velocity_b = b.velocity + cross(b.angular_velocity, xb) + (G / scale) * xb;
    return dot(contact.normal, velocity_b - velocity_a);
}

// Why no contact is missed: d(t) > 0 is the gap of a plane that separates the bodies at time t
// (or d = 0 and the isotropic bound w is used), and that gap shrinks at most at `rate` over
// [t, horizon] (header); so the bodies are apart on [t, t + d/rate), and the first contact
// time tau satisfies tau >= t + d/rate. The step is (d - m)/rate < d/rate with the margin
// m = tolerance/4, so by induction every t reached is before tau, with the bodies at least m
// apart, and the run stops at the first t where they are within the tolerance and closing: then
// they are between m and the tolerance apart. (While they are within the tolerance and opening,
// right after a collision, the step is m/rate when d < 2m: only then could the bodies come
// closer than m, by rounding-level amounts, as they are opening.)
namespace {

// Loose GJK runs (the fast loop's) stop at this relative accuracy while the distance bound is at
// least `accurate_below` contact tolerances; nearer, GJK converges fully, so the contact decision
// (d below one tolerance) is the reference's. A step then advances at least 95% as far as with
// the exact distance, for fewer GJK iterations on curved bodies (linear convergence).
constexpr double loose_accuracy = 0.05;
constexpr double accurate_below = 4;

// The distance bound for first_contact, and its plane's normal in `normal`: the reference's full
// GJK run (`warm` false), else a loose run started from `normal` (the pair's last plane) and,
// near contact, a full one started from the loose run's normal.
double advancement_distance(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double scale, double tolerance,
                            Vector3& normal, bool warm) {
    if (!warm) return distance(shape, a, b, scale, &normal);
    const double d = distance(shape, a, b, scale, &normal, SeparationHint{normal, loose_accuracy});
    if (d >= accurate_below * tolerance) return d;
    return distance(shape, a, b, scale, &normal, SeparationHint{normal, 0});
}

ContactPrediction advance_to_contact(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double a0, double G,
                                     double horizon, const ContactOptions& options, const SeparationHint* hint);

// How fast rotation can change the two bodies' support values along a fixed plane normal n:
// d/dt h(R^T n) = <omega x x, n> = <omega, x x n>, x the support point's offset, so at most
// |omega x n| a_h R_c (`reach` = a_h R_c; the reference's bound) and at most |omega| a_h L
// (`lever_reach` = a_h L) with the lever L = max |x x n| = max sqrt(|x|^2 - h^2) <=
// sqrt(R_c^2 - r_in^2) (|x| <= R_c, h >= r_in), 0.66 against R_c = 1.20 at p = 1.5. The fast
// loop takes the smaller; the reference passes lever_reach = reach and gets its own bound.
double spin_rate(const Vector3& omega_a, const Vector3& omega_b, const Vector3& n, double reach, double lever_reach) {
    const double turning_a = norm(cross(omega_a, n)), turning_b = norm(cross(omega_b, n));
    if (!(lever_reach < reach)) return reach * (turning_a + turning_b);  // the reference's expression, to the bit
    return std::min(reach * turning_a, lever_reach * norm(omega_a)) + std::min(reach * turning_b, lever_reach * norm(omega_b));
}

double lever(const SuperballShape& shape) {
    const double outer = shape.circumradius(), inner = shape.inradius();
    return std::sqrt(std::max(0.0, outer * outer - inner * inner));
}

}  // namespace

ContactPrediction first_contact(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double a0, double G,
                                double horizon, const ContactOptions& options) {
    return advance_to_contact(shape, a, b, a0, G, horizon, options, nullptr);
}

ContactPrediction first_contact(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double a0, double G,
                                double horizon, const ContactOptions& options, const SeparationHint& hint) {
    return advance_to_contact(shape, a, b, a0, G, horizon, options, &hint);
}

namespace {

ContactPrediction advance_to_contact(const SuperballShape& shape, const MovingBody& a, const MovingBody& b, double a0, double G,
                                     double horizon, const ContactOptions& options, const SeparationHint* hint) {
    if (!(a0 > 0) || !(G >= 0) || !(horizon >= 0)) throw std::invalid_argument("first_contact: needs a0 > 0, G >= 0, horizon >= 0");
    const bool ball = shape.p() == 1;
    const double radius = shape.circumradius();
    const double largest_scale = a0 + G * horizon;
    const Vector3 relative = b.velocity - a.velocity;
    const double spin = ball ? 0.0 : largest_scale * radius, lever_reach = hint ? largest_scale * lever(shape) : spin;  // spin_rate
    // The bound for any direction, used when no separating plane is known (d = 0).
    const double w = norm(relative) + 2 * G * radius + spin * (norm(a.angular_velocity) + norm(b.angular_velocity));
    ContactPrediction result;
    double t = 0;
    bool have_plane = false;
    Vector3 plane = hint ? hint->direction : Vector3{1, 0, 0};  // the fast loop starts GJK at the pair's last plane
    int since_gjk = 0;
    for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
        result.iterations = iteration;
        const MovingBody at_a = advance(a, t), at_b = advance(b, t);
        const double scale = a0 + G * t;
        const double tolerance = options.tolerance * scale * radius;
        // The gap of the last GJK plane, when it still separates by a clear margin: two support
        // values instead of a GJK run (near contact the plane turns slowly, and any separating
        // plane's gap is a lower bound on the distance). GJK again at least every 16 steps and
        // whenever the plane's gap is below twice the tolerance (for the contact decision).
        double d = -1;
        Vector3 n = plane;
        if (have_plane && since_gjk < 16) {
            d = plane_gap(shape, at_a, at_b, scale, n);
            if (!(d >= 2 * tolerance)) d = -1;
        }
        if (d < 0) {
            d = advancement_distance(shape, at_a, at_b, scale, tolerance, n, hint != nullptr);
            have_plane = !ball && d > 0;
            plane = result.normal = n;
            since_gjk = 0;
        } else {
            ++since_gjk;
        }
        if (d < tolerance) {
            const Contact touching = contact_along(shape, at_a, at_b, scale, n, d);
            if (normal_gap_rate(at_a, at_b, scale, G, touching) < 0) {
                result.outcome = ContactOutcome::contact;
                result.time = t;
                return result;
            }
        }
        // d > 0 is the gap of the plane with normal n (a lower bound on it for the bounding
        // spheres' case), and that fixed plane's gap shrinks at most at the closing normal
        // velocity, plus |omega x n| a R_c per body (the support value h_K(R^T n) changes at
        // <x, omega x n> with x the support offset, |x| <= R_c), plus G R_c per body: a
        // sharper bound than w, and as rigorous, while the plane separates the bodies.
        const double rate = d > 0 ? std::max(0.0, -dot(n, relative)) + 2 * G * radius +
                                        spin_rate(a.angular_velocity, b.angular_velocity, n, spin, lever_reach)
                                  : w;
        if (!(rate > 0)) break;  // the gap cannot shrink
        // Aim at a gap of a quarter of the tolerance rather than at 0, so that a contact is
        // reported with the bodies still apart by at least that much (d is a lower bound and the
        // gap shrinks at most at `rate`); opening bodies within the tolerance step by as much.
        const double margin = 0.25 * tolerance;
        t += std::max(d - margin, margin) / rate;
        if (!(t <= horizon)) break;
        if (iteration == options.max_iterations) {
            result.outcome = ContactOutcome::capped;
            result.time = t;
            return result;
        }
    }
    result.outcome = ContactOutcome::none;
    result.time = horizon;
    return result;
}

}  // namespace

CollisionResponse collide(double k, double scale, double G, const Contact& contact, MovingBody& a, MovingBody& b) {
    const double inertia = k * scale * scale;
    const double before = kinetic_energy(a, inertia) + kinetic_energy(b, inertia);
    const Vector3& n = contact.normal;
    const Vector3 xa = contact.point - a.center, xb = contact.point - b.center;
    // The rigid-body normal relative velocity u and the closing rate g of growth.
    const double u = dot(n, (b.velocity + cross(b.angular_velocity, xb)) - (a.velocity + cross(a.angular_velocity, xa)));
    const double g = (G / scale) * (dot(n, xa) - dot(n, xb));
    const double target = -u + 2 * g;
    const Vector3 arm_a = cross(xa, n), arm_b = cross(xb, n);
    const double inverse_mass = 2 + (dot(arm_a, arm_a) + dot(arm_b, arm_b)) / inertia;
    const double J = (target - u) / inverse_mass;
    a.velocity = a.velocity - J * n;
    b.velocity = b.velocity + J * n;
    a.angular_velocity = a.angular_velocity - (J / inertia) * arm_a;
    b.angular_velocity = b.angular_velocity + (J / inertia) * arm_b;
    CollisionResponse response;
    response.impulse = J;
    response.energy_change = kinetic_energy(a, inertia) + kinetic_energy(b, inertia) - before;
    return response;
}

}  // namespace superpack::sim
