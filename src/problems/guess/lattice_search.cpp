#include "superpack/problems/guess/lattice_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <random>

#include "superpack/problems/guess/compass_pass.hpp"
#include "superpack/problems/guess/difference_gauge.hpp"
#include "superpack/solve/approximate_inverse.hpp"
#include "superpack/solve/dense3.hpp"

namespace superpack {

namespace {

using Triple = std::array<long, 3>;
using dense::dot;
using dense::max_norm;
using dense::Vector3;

// One coefficient triple per +-pair with every |c_i| <= 2: after reduction the shortest vectors
// of a 3-dimensional lattice lie there (a guess; the certification enumerates a proved box).
const std::vector<Triple>& short_triples() {
    static const std::vector<Triple> triples = [] {
        std::vector<Triple> all;
        for (long a = -2; a <= 2; ++a)
            for (long b = -2; b <= 2; ++b)
                for (long c = -2; c <= 2; ++c) {
                    const bool first_positive = a > 0 || (a == 0 && (b > 0 || (b == 0 && c > 0)));
                    if (first_positive) all.push_back({a, b, c});
                }
        return all;
    }();
    return triples;
}

Vector3 combine(const Triple& c, const DoubleBasis& b) {
    Vector3 v{};
    for (int j = 0; j < 3; ++j) v[j] = c[0] * b[0][j] + c[1] * b[1][j] + c[2] * b[2][j];
    return v;
}

// The most coefficient pairs for_each_in_cube walks: a basis that needs more is so skewed that
// the search treats it as no packing.
constexpr double max_cube_pairs = 1e5;

// The coefficient bounds of for_each_in_cube, the one to solve for (the widest) last; nothing
// when they take more than max_cube_pairs pairs or B is singular.
struct CubeLimits {
    std::array<long, 3> limit;
    int first, second, last;
};
std::optional<CubeLimits> cube_limits(const DoubleBasis& b, double bound) {
    const double det = determinant(b);
    if (!(std::fabs(det) > 0) || !(bound < HUGE_VAL)) return std::nullopt;
    CubeLimits cube{};
    for (int k = 0; k < 3; ++k) {
        // Column k of B^-1 is the cross product of the other two rows over det.
        const Vector3& u = b[(k + 1) % 3];
        const Vector3& w = b[(k + 2) % 3];
        const Vector3 cross = dense::cross(u, w);
        const double reach = bound * (std::fabs(cross[0]) + std::fabs(cross[1]) + std::fabs(cross[2])) / std::fabs(det);
        if (!(reach < 1e6)) return std::nullopt;
        cube.limit[k] = static_cast<long>(std::floor(reach * (1 + 1e-9)));
    }
    cube.last = 0;
    for (int k = 1; k < 3; ++k)
        if (cube.limit[k] > cube.limit[cube.last]) cube.last = k;
    cube.first = (cube.last + 1) % 3;
    cube.second = (cube.last + 2) % 3;
    if ((2.0 * cube.limit[cube.first] + 1) * (2.0 * cube.limit[cube.second] + 1) > max_cube_pairs) return std::nullopt;
    return cube;
}

// Calls visit(c, c B) for one c per +-pair of every nonzero lattice vector with max |v_i| < bound
// (and perhaps a few more), in floating point: |c_k| <= bound * sum_j |(B^-1)_jk| bounds two
// coefficients, and each coordinate's bound |v_j| < bound gives the third an interval. False,
// with nothing visited, when that takes more than max_cube_pairs pairs or B is singular.
template <class Visit>
bool for_each_in_cube(const DoubleBasis& b, double bound, Visit&& visit) {
    const std::optional<CubeLimits> cube = cube_limits(b, bound);
    if (!cube) return false;
    const std::array<long, 3>& limit = cube->limit;
    const int first = cube->first, second = cube->second, last = cube->last;
    const double reach = bound * (1 + 1e-9);
    for (long a = -limit[first]; a <= limit[first]; ++a)
        for (long c = -limit[second]; c <= limit[second]; ++c) {
            Vector3 partial{};
            for (int j = 0; j < 3; ++j) partial[j] = a * b[first][j] + c * b[second][j];
            double low = -HUGE_VAL, high = HUGE_VAL;
            for (int j = 0; j < 3; ++j) {
                const double step = b[last][j];
                if (step == 0) {
                    if (!(std::fabs(partial[j]) < reach)) low = HUGE_VAL;
                    continue;
                }
                const double x = (-reach - partial[j]) / step, y = (reach - partial[j]) / step;
                low = std::max(low, std::min(x, y));
                high = std::min(high, std::max(x, y));
            }
            if (!(low <= high)) continue;
            for (long t = static_cast<long>(std::ceil(low)); t <= static_cast<long>(std::floor(high)); ++t) {
                Triple triple{};
                triple[first] = a;
                triple[second] = c;
                triple[last] = t;
                const int lead = triple[0] != 0 ? 0 : triple[1] != 0 ? 1 : 2;
                if (triple[lead] <= 0) continue;  // zero, or the other of its +-pair
                visit(triple, combine(triple, b));
            }
        }
    return true;
}

// Size reduction in the Euclidean inner product, rows sorted by length, det > 0: a basis in
// which the short triples above find the shortest vectors.
void reduce(DoubleBasis& b) {
    for (int round = 0; round < 100; ++round) {
        bool changed = false;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                if (i == j) continue;
                const double k = std::nearbyint(dot(b[i], b[j]) / dot(b[j], b[j]));
                if (k != 0) {
                    for (int c = 0; c < 3; ++c) b[i][c] -= k * b[j][c];
                    changed = true;
                }
            }
        if (!changed) break;
    }
    std::sort(b.begin(), b.end(), [](const Vector3& x, const Vector3& y) { return dot(x, x) < dot(y, y); });
    if (determinant(b) < 0)
        for (double& x : b[2]) x = -x;
}

DoubleBasis scaled(DoubleBasis b, double factor) {
    for (auto& row : b)
        for (double& x : row) x *= factor;
    return b;
}

// The shortest packing norm over the short triples and `extra` (the search's cuts below 1/2).
double shortest_over(const DoubleBasis& b, double p, const std::vector<Triple>& extra) {
    double shortest = HUGE_VAL;
    for (const std::vector<Triple>* triples : {&short_triples(), &extra})
        for (const Triple& c : *triples) {
            const Vector3 v = combine(c, b);
            // 2 ||v||_D is at least max |v_i|: no need to evaluate a vector that cannot be shorter.
            if (max_norm(v) < shortest) shortest = std::min(shortest, packing_norm(v, p));
        }
    return shortest;
}

// log|det B| - 3 log(lambda / 2): minus the log of the density, up to log V.
double objective(const DoubleBasis& b, double p, const std::vector<Triple>& extra = {}) {
    const double d = std::fabs(determinant(b));
    const double shortest = shortest_over(b, p, extra);
    if (!(d > 0) || !(shortest > 0)) return HUGE_VAL;
    // Below 1/2 the short triples and cuts see only part of the lattice: a step to a lattice too
    // skewed for the cuts' enumeration would leave it unseen, so it is refused.
    if (p < 0.5 && !cube_limits(b, shortest)) return HUGE_VAL;
    return std::log(d) - 3 * std::log(shortest / 2);
}

// Compass search over the nine entries, with the coordinate directions and fresh random ones
// each round (F is a minimum of smooth functions: at a kink only a few directions descend).
DoubleBasis pattern_search(DoubleBasis b, double p, std::mt19937_64& random, long& evaluations,
                           const std::vector<Triple>& extra) {
    std::normal_distribution<double> normal;
    double value = objective(b, p, extra);
    ++evaluations;
    const long budget = evaluations + 30000;
    for (double step = 0.05; step > 1e-12 && evaluations < budget;) {
        std::vector<DoubleBasis> directions;
        for (int k = 0; k < 9; ++k) {
            DoubleBasis d{};
            d[k / 3][k % 3] = 1;
            directions.push_back(d);
            directions.push_back(scaled(d, -1));
        }
        for (int k = 0; k < 18; ++k) {
            DoubleBasis d{};
            double length = 0;
            for (auto& row : d)
                for (double& x : row) {
                    x = normal(random);
                    length += x * x;
                }
            directions.push_back(scaled(d, 1 / std::sqrt(length)));
        }
        const auto moved = [step](const DoubleBasis& from, const DoubleBasis& d) {
            DoubleBasis trial = from;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) trial[i][j] += step * d[i][j];
            return trial;
        };
        const auto f = [&](const DoubleBasis& trial) { return objective(trial, p, extra); };
        if (!compass_pass(b, value, directions, moved, f, evaluations)) step /= 2;
    }
    return b;
}

// Newton's method on the KKT system of min det B subject to ||c_i B|| = 2 for the active
// triples c_i (unknowns: the nine entries and one multiplier each), with a central-difference
// Jacobian. A guess: it returns the solution only when it converged with positive multipliers.
struct KktSystem {
    double p;
    std::vector<Triple> active;

    std::vector<double> residual(const std::vector<double>& x) const {
        DoubleBasis b{};
        for (int k = 0; k < 9; ++k) b[k / 3][k % 3] = x[k];
        std::vector<double> r(9 + active.size(), 0.0);
        // Stationarity: d det / d b_kj = the cofactor, minus sum_i mu_i d||c_i B|| / d b_kj.
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) {
                const int k1 = (k + 1) % 3, k2 = (k + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
                r[3 * k + j] = b[k1][j1] * b[k2][j2] - b[k1][j2] * b[k2][j1];
            }
        for (std::size_t i = 0; i < active.size(); ++i) {
            const Vector3 v = combine(active[i], b);
            const double n = norm_2p(v, p);
            const double mu = x[9 + i];
            for (int k = 0; k < 3; ++k)
                for (int j = 0; j < 3; ++j)
                    r[3 * k + j] -= mu * active[i][k] * std::copysign(std::pow(std::fabs(v[j]) / n, 2 * p - 1), v[j]);
            r[9 + i] = n - 2;
        }
        return r;
    }
};

double size_of(const std::vector<double>& r) {
    double largest = 0;
    for (double x : r) largest = std::max(largest, std::fabs(x));
    return largest;
}

}  // namespace

namespace {

// Newton's method on the KKT system from x = (B, mu); the solution only when it converged with
// positive multipliers and the active vectors still the shortest, no worse than the start b.
std::optional<KktPoint> polish(const KktSystem& system, std::vector<double> x, const DoubleBasis& b) {
    const std::size_t n = x.size();
    const double p = system.p;
    for (int iteration = 0; iteration < 40; ++iteration) {
        const std::vector<double> r = system.residual(x);
        if (size_of(r) < 1e-14) break;
        DoubleMatrix jacobian(n);
        for (std::size_t j = 0; j < n; ++j) {
            const double h = 1e-7 * std::max(1.0, std::fabs(x[j]));
            std::vector<double> up = x, down = x;
            up[j] += h;
            down[j] -= h;
            const std::vector<double> r_up = system.residual(up), r_down = system.residual(down);
            for (std::size_t i = 0; i < n; ++i) jacobian(i, j) = (r_up[i] - r_down[i]) / (2 * h);
        }
        const auto inverse = approximate_inverse(jacobian);
        if (!inverse) return std::nullopt;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) x[i] -= (*inverse)(i, j) * r[j];
    }
    if (!(size_of(system.residual(x)) < 1e-12)) return std::nullopt;
    for (std::size_t i = 9; i < n; ++i)
        if (!(x[i] > 0)) return std::nullopt;
    KktPoint point;
    for (int k = 0; k < 9; ++k) point.basis[k / 3][k % 3] = x[k];
    point.multipliers.assign(x.begin() + 9, x.end());
    // The polished lattice must still have the active vectors as its shortest ones.
    if (!(shortest_norm(point.basis, p) > 2 * (1 - 1e-12)) || !(objective(point.basis, p) <= objective(b, p) + 1e-12))
        return std::nullopt;
    return point;
}

}  // namespace

std::optional<KktPoint> kkt_point(const DoubleBasis& b, double p, const std::vector<std::array<long, 3>>& active) {
    const std::size_t n = 9 + active.size();
    if (active.empty() || active.size() > 9) return std::nullopt;
    const KktSystem system{p, active};
    std::vector<double> x(n, 0.0);
    for (int k = 0; k < 9; ++k) x[k] = b[k / 3][k % 3];
    // Multipliers from least squares on the stationarity rows at the start.
    {
        std::vector<double> at = x;
        const std::vector<double> cofactor = system.residual(at);  // with mu = 0: the cofactors
        std::vector<std::vector<double>> gradient(active.size(), std::vector<double>(9));
        for (std::size_t i = 0; i < active.size(); ++i) {
            at[9 + i] = 1;
            const std::vector<double> with = system.residual(at);
            for (int k = 0; k < 9; ++k) gradient[i][k] = cofactor[k] - with[k];
            at[9 + i] = 0;
        }
        DoubleMatrix normal(active.size());
        std::vector<double> right(active.size(), 0.0);
        for (std::size_t i = 0; i < active.size(); ++i) {
            for (std::size_t j = 0; j < active.size(); ++j)
                for (int k = 0; k < 9; ++k) normal(i, j) += gradient[i][k] * gradient[j][k];
            for (int k = 0; k < 9; ++k) right[i] += gradient[i][k] * cofactor[k];
        }
        const auto inverse = approximate_inverse(normal);
        if (!inverse) return std::nullopt;
        for (std::size_t i = 0; i < active.size(); ++i)
            for (std::size_t j = 0; j < active.size(); ++j) x[9 + i] += (*inverse)(i, j) * right[j];
    }
    return polish(system, x, b);
}

std::optional<KktPoint> kkt_point(const KktPoint& start, double p, const std::vector<std::array<long, 3>>& active) {
    if (active.empty() || active.size() > 9 || start.multipliers.size() != active.size()) return std::nullopt;
    std::vector<double> x;
    for (const auto& row : start.basis) x.insert(x.end(), row.begin(), row.end());
    x.insert(x.end(), start.multipliers.begin(), start.multipliers.end());
    return polish(KktSystem{p, active}, x, start.basis);
}

namespace {

std::vector<Triple> near_shortest(const DoubleBasis& b, double p, double tolerance) {
    const double shortest = shortest_norm(b, p);
    std::vector<Triple> near;
    auto visit = [&](const Triple& c, const Vector3& v) {
        if (packing_norm(v, p) <= shortest * (1 + tolerance)) near.push_back(c);
    };
    if (p >= 0.5) {
        for (const Triple& c : short_triples()) visit(c, combine(c, b));
    } else {
        for_each_in_cube(b, shortest * (1 + tolerance), visit);
    }
    return near;
}

// Reduced and scaled to shortest packing norm 2; nothing when the basis is too skewed to
// enumerate (shortest_norm 0).
std::optional<DoubleBasis> normalised(DoubleBasis b, double p) {
    reduce(b);
    const double shortest = shortest_norm(b, p);
    if (!(shortest > 0)) return std::nullopt;
    return scaled(b, 2 / shortest);
}

}  // namespace

double norm_2p(const std::array<double, 3>& v, double p) {
    const double largest = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
    if (largest == 0) return 0;
    double sum = 0;
    for (double x : v) sum += std::pow(std::fabs(x) / largest, 2 * p);
    return largest * std::pow(sum, 1 / (2 * p));
}

double packing_norm(const std::array<double, 3>& v, double p) {
    return p >= 0.5 ? norm_2p(v, p) : 2 * difference_gauge(v, p);
}

double shortest_norm(const DoubleBasis& basis, double p) {
    double shortest = shortest_over(basis, p, {});
    // Below 1/2 the packing norm is far from Euclidean (a thin cross's arm reaches through many
    // lattice cells), so the short triples of a reduced basis may miss the shortest vector: every
    // vector that could be shorter, max |v_i| below the shortest so far, is visited.
    auto visit = [&](const Triple&, const Vector3& v) {
        if (max_norm(v) < shortest) shortest = std::min(shortest, packing_norm(v, p));
    };
    if (p < 0.5 && !for_each_in_cube(basis, shortest, visit)) return 0;
    return shortest;
}

SearchResult search_dense_lattices(double p, double volume, const std::vector<SearchStart>& starts,
                                   const SearchOptions& options) {
    std::mt19937_64 random(options.seed);
    std::uniform_real_distribution<double> uniform(-1, 1);
    std::vector<SearchStart> all;
    for (const SearchStart& start : starts) {
        all.push_back(start);
        for (int k = 0; k < options.perturbed_starts; ++k) {
            SearchStart perturbed{start.name + ", perturbed " + std::to_string(k + 1), start.basis};
            for (auto& row : perturbed.basis)
                for (double& x : row) x *= 1 + 0.05 * uniform(random);
            all.push_back(perturbed);
        }
    }
    for (int k = 0; k < options.random_starts; ++k) {
        SearchStart start{"random " + std::to_string(k + 1), {}};
        do {
            for (auto& row : start.basis)
                for (double& x : row) x = uniform(random);
        } while (std::fabs(determinant(start.basis)) < 0.05);
        all.push_back(start);
    }
    SearchResult result;
    const auto begin = std::chrono::steady_clock::now();
    for (const SearchStart& start : all) {
        const std::optional<DoubleBasis> first = normalised(start.basis, p);
        if (!first) continue;
        DoubleBasis b = *first;
        // Below 1/2 the objective over the short triples alone may miss the shortest vector, and
        // the whole enumeration costs hundreds of vectors an evaluation: the vectors the search
        // has missed join its objective as cuts, and it runs again, until none is missed.
        // A search that runs into a lattice too skewed to enumerate has lost track of its
        // shortest vector: it gives no candidate.
        std::vector<Triple> cuts;
        bool enumerable = true;
        for (int round = 0; round < 10 && enumerable; ++round) {
            b = pattern_search(b, p, random, result.evaluations, cuts);
            if (p >= 0.5) break;
            const double shortest = shortest_over(b, p, cuts);
            const std::size_t before = cuts.size();
            enumerable = for_each_in_cube(b, shortest, [&](const Triple& c, const Vector3& v) {
                if (packing_norm(v, p) < shortest * (1 - 1e-12)) cuts.push_back(c);
            });
            if (cuts.size() == before) break;
        }
        const std::optional<DoubleBasis> end = normalised(b, p);
        if (!enumerable || !end) continue;
        SearchCandidate candidate{start.name, *end, 0, {}};
        // The pattern search stops near, not at, a kink: the active set is guessed at growing
        // tolerances, and the first that Newton's method turns into a KKT point is kept. Below
        // p = 1/2 the constraints are the difference body's gauge, which the KKT system does not
        // model: the pattern search's end point is the candidate.
        for (double tolerance : {1e-7, 1e-5, 1e-4, 1e-3, 1e-2}) {
            if (p < 0.5) break;
            const std::optional<KktPoint> point = kkt_point(*end, p, near_shortest(*end, p, tolerance));
            const std::optional<DoubleBasis> polished = point ? normalised(point->basis, p) : std::nullopt;
            if (polished) {
                candidate.basis = *polished;
                break;
            }
        }
        candidate.density = volume / std::fabs(determinant(candidate.basis));
        candidate.near_contacts = near_shortest(candidate.basis, p, 1e-9);
        result.candidates.push_back(candidate);
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    std::stable_sort(result.candidates.begin(), result.candidates.end(),
                     [](const SearchCandidate& a, const SearchCandidate& b) { return a.density > b.density; });
    return result;
}

}  // namespace superpack
