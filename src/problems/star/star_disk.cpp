#include "superpack/problems/star/star_disk.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "superpack/geometry/superball.hpp"
#include "superpack/problems/guess/compass_pass.hpp"
#include "superpack/problems/guess/lattice_search.hpp"

namespace superpack {

namespace {

using PlanePoint = std::array<double, 4>;  // u1, u2, w1, w2

double plane_determinant(const PlanePoint& b) { return b[0] * b[3] - b[1] * b[2]; }

// The shortest packing norm 2 ||v||_D over the plane lattice: every vector shorter than s has
// max |v_i| < s (2 ||v||_D >= max |v_i|), so with a = (v x w) / det its coefficients satisfy
// |a| < s (|w1| + |w2|) / |det|, and likewise b. 0 for a basis too skewed to enumerate.
double plane_shortest(const PlanePoint& b, double p) {
    const double det = std::fabs(plane_determinant(b));
    if (!(det > 0)) return 0;
    auto norm = [&](double a, double c) { return packing_norm({a * b[0] + c * b[2], a * b[1] + c * b[3], 0}, p); };
    double shortest = std::min({norm(1, 0), norm(0, 1), norm(1, 1), norm(1, -1)});
    const double reach_a = shortest * (std::fabs(b[2]) + std::fabs(b[3])) / det;
    const double reach_b = shortest * (std::fabs(b[0]) + std::fabs(b[1])) / det;
    if (!(reach_a * reach_b < 1e5)) return 0;
    for (long a = 0; a <= static_cast<long>(reach_a); ++a)
        for (long c = -static_cast<long>(reach_b); c <= static_cast<long>(reach_b); ++c) {
            if (a == 0 && c <= 0) continue;  // one of v, -v
            const double x = a * b[0] + c * b[2], y = a * b[1] + c * b[3];
            if (std::max(std::fabs(x), std::fabs(y)) < shortest) shortest = std::min(shortest, norm(a, c));
        }
    return shortest;
}

// Minus the log of the density, up to log A: scale-free.
double objective(const PlanePoint& b, double p) {
    const double shortest = plane_shortest(b, p);
    if (!(shortest > 0)) return HUGE_VAL;
    return std::log(std::fabs(plane_determinant(b))) - 2 * std::log(shortest / 2);
}

// Compass search over the four entries and random directions, the step halved when none helps.
PlanePoint descend(PlanePoint b, double p, std::mt19937_64& random) {
    std::normal_distribution<double> normal;
    double value = objective(b, p);
    long evaluations = 0;
    for (double step = 0.05; step > 1e-12;) {
        std::vector<PlanePoint> directions;
        for (int k = 0; k < 16; ++k) {
            PlanePoint d{};
            if (k < 8) {
                d[k / 2] = k % 2 ? -1 : 1;
            } else {
                for (double& x : d) x = normal(random);
            }
            const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + d[3] * d[3]);
            for (double& x : d) x *= step / length;
            directions.push_back(d);
        }
        const auto moved = [](const PlanePoint& from, const PlanePoint& d) {
            return PlanePoint{from[0] + d[0], from[1] + d[1], from[2] + d[2], from[3] + d[3]};
        };
        if (!compass_pass(b, value, directions, moved, [p](const PlanePoint& x) { return objective(x, p); }, evaluations))
            step /= 2;
    }
    return b;
}

struct PlaneStart {
    std::string name;
    PlanePoint basis;
};

std::vector<PlaneStart> plane_starts(double p) {
    const double q = 2 * p;
    std::vector<PlaneStart> starts{{"diamond (1, 1), (1, -1)", {1, 1, 1, -1}}, {"square 2Z^2", {2, 0, 0, 2}}};
    for (double h : {0.2, 0.4, 0.6, 0.8}) {
        const double r = std::pow(1 - std::pow(h, q), 1 / q);
        starts.push_back({"pinwheel h = " + std::to_string(h).substr(0, 3), {1 + r, h, -h, 1 + r}});
    }
    std::mt19937_64 random(1);
    std::uniform_real_distribution<double> entry(-2, 2);
    for (int k = 1; k <= 8; ++k) starts.push_back({"random " + std::to_string(k), {entry(random), entry(random), entry(random), entry(random)}});
    return starts;
}

// The guess scaled to touch (shortest packing norm 2), then by 1 + 2^-40 and made exact.
PlaneBasis exact_scaled(const PlanePoint& b, double shortest) {
    const Rational scale = (1 + Rational(1) / Rational(mpz_class(1) << 40)) * Rational(2 / shortest);
    return {{{Rational(b[0]) * scale, Rational(b[1]) * scale}, {Rational(b[2]) * scale, Rational(b[3]) * scale}}};
}

Basis<Rational> space_lattice(const PlaneBasis& basis) {
    return {{{basis[0][0], basis[0][1], 0}, {basis[1][0], basis[1][1], 0}, {0, 0, 2}}};
}

template <class Field>
StarDiskLattice<typename Field::Interval> best_lattice(const Rational& p, const Field& field) {
    if (!(p > 0 && p < Rational(1, 2))) throw InputError("the concave superdisk search needs 0 < p < 1/2");
    using I = typename Field::Interval;
    const I area = enclose_superdisk_area(p, field);
    StarDiskLattice<I> best{area, area / field.integer(2), Outcome::undecided, "", "", {}, std::nullopt, 0};
    const double p_double = p.get_d();
    struct Find {
        std::string start;
        PlanePoint basis;
        double shortest, density;
    };
    std::vector<Find> finds;
    std::mt19937_64 random(1);
    for (const PlaneStart& start : plane_starts(p_double)) {
        const PlanePoint end = descend(start.basis, p_double, random);
        const double shortest = plane_shortest(end, p_double);
        if (!(shortest > 0)) continue;
        finds.push_back({start.name, end, shortest, shortest * shortest / 4 / std::fabs(plane_determinant(end))});
    }
    std::sort(finds.begin(), finds.end(), [](const Find& a, const Find& b) { return a.density > b.density; });
    best.reason = "no find of the search was certified a packing";
    int checked = 0;
    for (std::size_t k = 0; k < finds.size() && checked < 4; ++k) {
        if (k > 0 && finds[k].density > finds[k - 1].density * (1 - 1e-9)) continue;  // a repeat
        ++checked;
        const PlaneBasis exact = exact_scaled(finds[k].basis, finds[k].shortest);
        const LatticeCheck<I> check = check_exact_lattice(space_lattice(exact), p, field);
        best.candidates_checked += static_cast<long>(check.evaluated.size());
        if (check.verdict != Outcome::proved) continue;
        const Rational det = exact[0][0] * exact[1][1] - exact[0][1] * exact[1][0];
        const I phi = best.area / field.rational(abs(det));
        if (best.phi && !(mid_double(phi) > mid_double(*best.phi))) continue;
        best.status = Outcome::proved;
        best.reason = "certified a packing by the star test of the lattice with rows (u, 0), (w, 0), (0, 0, 2)";
        best.start = finds[k].start;
        best.basis = exact;
        best.phi = phi;
    }
    return best;
}

}  // namespace

LatticeCheck<DInterval> check_plane_star_lattice(const PlaneBasis& basis, const Rational& p, const DoubleField& field) {
    return check_exact_lattice(space_lattice(basis), p, field);
}
LatticeCheck<Ball> check_plane_star_lattice(const PlaneBasis& basis, const Rational& p, const BallField& field) {
    return check_exact_lattice(space_lattice(basis), p, field);
}
StarDiskLattice<DInterval> best_star_disk_lattice(const Rational& p, const DoubleField& field) { return best_lattice(p, field); }
StarDiskLattice<Ball> best_star_disk_lattice(const Rational& p, const BallField& field) { return best_lattice(p, field); }

}  // namespace superpack
