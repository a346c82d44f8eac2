#include "superpack/sim/overlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace superpack::sim {

Vector3 support_point(const SuperballShape& shape, const Placement& body, const Vector3& direction) {
    return body.center + apply(body.rotation, shape.support_point(apply_transpose(body.rotation, direction)));
}

double support_value(const SuperballShape& shape, const Placement& body, const Vector3& direction) {
    return dot(body.center, direction) + shape.support_value(apply_transpose(body.rotation, direction));
}

namespace {

// GJK's stopping rule: |v| - <v, w>/|v| at most this much relative to |v|, or this much
// absolute in circumradii (which decides contact at 1e-12 with room for rounding).
constexpr double relative_gap = 1e-10;
constexpr double absolute_gap = 1e-13;
// GJK converges only linearly on curved bodies: near contact the boolean test takes up to
// about 55 steps and the distance test about 70 (smooth superballs, p = 2 to 50; polytope-like
// bodies take fewer). The cap only guarantees an end; a run it stops counts as overlapping
// unless a separating plane was found.
constexpr int iteration_cap = 128;

Vector3 unit_or_first_axis(const Vector3& v) {
    const double length = norm(v);
    if (!(length > 0) || !std::isfinite(length)) return {1, 0, 0};
    return (1 / length) * v;
}


// Up to four support points of D.
struct Simplex {
    std::array<Vector3, 4> points{};
    int size = 0;
    void add(const Vector3& w) { points[size++] = w; }
};

// The point of conv(simplex) nearest to 0 and the least face of the simplex holding it.
struct Nearest {
    Vector3 point{};
    Simplex simplex;
    bool contains_origin = false;
};

Nearest vertex(const Vector3& a) {
    Nearest result;
    result.point = a;
    result.simplex.add(a);
    return result;
}

Nearest segment(const Vector3& a, const Vector3& b) {
    const Vector3 ab = b - a;
    const double length_squared = dot(ab, ab);
    if (!(length_squared > 0)) return vertex(a);
    const double t = -dot(a, ab) / length_squared;
    if (t <= 0) return vertex(a);
    if (t >= 1) return vertex(b);
    Nearest result;
    result.point = a + t * ab;
    result.simplex.add(a);
    result.simplex.add(b);
    return result;
}

Nearest nearer(const Nearest& x, const Nearest& y) { return dot(y.point, y.point) < dot(x.point, x.point) ? y : x; }

// A triangle's nearest point is inside it, the projection of 0 on its plane, when the
// barycentric coordinates of that projection are all >= 0, otherwise on an edge. The edges
// are all tried, rather than one picked by Voronoi regions: the regions' products cancel on
// the long thin triangles that GJK builds near contact (near-cubes at large p), and a wrong
// pick then makes |v| grow. A point of the triangle comes back either way.
Nearest triangle(const Vector3& a, const Vector3& b, const Vector3& c) {
    const Vector3 normal = cross(b - a, c - a);
    const double normal_squared = dot(normal, normal);
    if (normal_squared > 0) {
        // The projection p0 is parallel to the normal, so <normal, (b - p0) x (c - p0)> is
        // <normal, b x c>, and so on round.
        const double weight_a = dot(normal, cross(b, c)), weight_b = dot(normal, cross(c, a)), weight_c = dot(normal, cross(a, b));
        if (weight_a >= 0 && weight_b >= 0 && weight_c >= 0) {
            Nearest result;
            // The projection itself, which keeps the normal component (the distance) accurate
            // where a barycentric combination would add rounding along the face.
            result.point = (dot(a, normal) / normal_squared) * normal;
            result.simplex.add(a);
            result.simplex.add(b);
            result.simplex.add(c);
            return result;
        }
    }
    return nearer(nearer(segment(a, b), segment(a, c)), segment(b, c));
}

double volume(const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d) {
    return dot(b - a, cross(c - a, d - a));
}

// 0 is inside when the four tetrahedra it makes with the faces all have the orientation of
// the whole; otherwise (and for a flat tetrahedron) the nearest point is the nearest of the
// four faces' nearest points, all tried for the reason given at triangle().
Nearest tetrahedron(const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d) {
    const Vector3 origin{0, 0, 0};
    const double whole = volume(a, b, c, d);
    const std::array<double, 4> parts{volume(origin, b, c, d), volume(a, origin, c, d), volume(a, b, origin, d), volume(a, b, c, origin)};
    bool inside = whole != 0;
    for (double part : parts) inside = inside && (whole > 0 ? part > 0 : part < 0);
    if (inside) {
        Nearest result;
        result.contains_origin = true;
        return result;
    }
    return nearer(nearer(triangle(a, b, c), triangle(a, b, d)), nearer(triangle(a, c, d), triangle(b, c, d)));
}

Nearest nearest_to_origin(const Simplex& s) {
    const auto& p = s.points;
    switch (s.size) {
        case 1: return vertex(p[0]);
        case 2: return segment(p[0], p[1]);
        case 3: return triangle(p[0], p[1], p[2]);
        default: return tetrahedron(p[0], p[1], p[2], p[3]);
    }
}

bool warm(const SeparationHint& hint) { return dot(hint.direction, hint.direction) > 0; }

// Where GJK's search starts: a's centre minus b's, a point of D, or with a hint -|delta| times
// its direction, which is no point of D: |v| is then no upper bound on the distance, and the
// first step may not conclude convergence from it.
Vector3 first_search_vector(const Vector3& delta, const SeparationHint& hint) {
    return warm(hint) ? (-norm(delta)) * hint.direction : -delta;
}

}  // namespace

namespace detail {

Separation gjk(const SuperballShape& shape, const Placement& a, const Placement& b, bool stop_at_first_plane, GjkTrace* trace,
               const SeparationHint& hint) {
    const double size = shape.circumradius();
    const double tolerance = contact_tolerance * size;
    // Coordinates relative to a's center, so that only the bodies' difference enters the
    // rounding errors, not how far from the origin the cell puts them.
    const Vector3 delta = b.center - a.center;
    const Separation overlap{true, 0, unit_or_first_axis(delta)};
    if (trace) *trace = GjkTrace{};
    const double center_distance = norm(delta);
    if (!std::isfinite(center_distance)) return overlap;
    // Bounding spheres apart: the plane through the midpoint, normal to delta, separates them.
    if (center_distance > 2 * size) return {false, center_distance - 2 * size, (1 / center_distance) * delta};
    // Inscribed balls overlapping: so do the bodies.
    if (center_distance < 2 * shape.inradius()) return overlap;

    const Placement body_a{{0, 0, 0}, a.rotation}, body_b{delta, b.rotation};
    const auto support_of_difference = [&](const Vector3& direction) {
        return support_point(shape, body_a, direction) - support_point(shape, body_b, -direction);
    };

    Vector3 v = first_search_vector(delta, hint);
    Simplex simplex;
    double best_gap = -std::numeric_limits<double>::infinity();
    Vector3 best_normal = unit_or_first_axis(delta);
    for (int iteration = 1; iteration <= iteration_cap; ++iteration) {
        if (trace) trace->iterations = iteration;
        const double length = norm(v);
        const Vector3 w = support_of_difference(-v);
        // min over D of <v/|v|, z> is attained at w: the plane with normal -v/|v| leaves a gap
        // of <v, w>/|v| between a and b.
        const double gap = dot(v, w) / length;
        if (gap > best_gap) {
            best_gap = gap;
            best_normal = (-1 / length) * v;
        }
        if (stop_at_first_plane && gap > tolerance) break;
        const double accuracy = std::max(relative_gap, hint.relative_accuracy);
        if (!(iteration == 1 && warm(hint)) && length - gap <= std::max(absolute_gap * size, accuracy * length)) {
            if (trace) trace->converged = true;
            break;
        }
        Simplex next = simplex;
        next.add(w);
        const Nearest nearest = nearest_to_origin(next);
        if (nearest.contains_origin) return {true, 0, best_normal};
        const double next_length = norm(nearest.point);
        if (next_length <= tolerance) return {true, 0, best_normal};  // a point of D within the tolerance of 0
        // No decrease: rounding has taken over from geometry; the best plane so far decides.
        // (Not at the first step, whose v, the center difference, is no point of the simplex.)
        if (simplex.size > 0 && !(next_length < length)) {
            if (trace) trace->stalled = true;
            break;
        }
        simplex = nearest.simplex;
        v = nearest.point;
        if (trace && iteration == iteration_cap) trace->capped = true;
    }
    return {!(best_gap > tolerance), best_gap > tolerance ? best_gap : 0, best_normal};
}

}  // namespace detail

bool overlapping(const SuperballShape& shape, const Placement& a, const Placement& b) {
    return detail::gjk(shape, a, b, true, nullptr).overlapping;
}

Separation separation(const SuperballShape& shape, const Placement& a, const Placement& b) {
    return detail::gjk(shape, a, b, false, nullptr);
}

Separation separation(const SuperballShape& shape, const Placement& a, const Placement& b, const SeparationHint& hint) {
    return detail::gjk(shape, a, b, false, nullptr, hint);
}

}  // namespace superpack::sim
