#include "superpack/problems/lattice_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <random>

#include "superpack/solve/approximate_inverse.hpp"

namespace superpack {

namespace {

using Triple = std::array<long, 3>;
using Vector = std::array<double, 3>;

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

Vector combine(const Triple& c, const DoubleBasis& b) {
    Vector v{};
    for (int j = 0; j < 3; ++j) v[j] = c[0] * b[0][j] + c[1] * b[1][j] + c[2] * b[2][j];
    return v;
}

double dot(const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

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
    std::sort(b.begin(), b.end(), [](const Vector& x, const Vector& y) { return dot(x, x) < dot(y, y); });
    if (determinant(b) < 0)
        for (double& x : b[2]) x = -x;
}

DoubleBasis scaled(DoubleBasis b, double factor) {
    for (auto& row : b)
        for (double& x : row) x *= factor;
    return b;
}

// log|det B| - 3 log(lambda / 2): minus the log of the density, up to log V.
double objective(const DoubleBasis& b, double p) {
    const double d = std::fabs(determinant(b));
    const double shortest = shortest_norm(b, p);
    if (!(d > 0) || !(shortest > 0)) return HUGE_VAL;
    return std::log(d) - 3 * std::log(shortest / 2);
}

// Compass search over the nine entries, with the coordinate directions and fresh random ones
// each round (F is a minimum of smooth functions: at a kink only a few directions descend).
DoubleBasis pattern_search(DoubleBasis b, double p, std::mt19937_64& random, long& evaluations) {
    std::normal_distribution<double> normal;
    double value = objective(b, p);
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
        bool improved = false;
        for (const DoubleBasis& d : directions) {
            DoubleBasis trial = b;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) trial[i][j] += step * d[i][j];
            const double trial_value = objective(trial, p);
            ++evaluations;
            if (trial_value < value - 1e-15) {
                b = trial;
                value = trial_value;
                improved = true;
            }
        }
        if (!improved) step /= 2;
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
            const Vector v = combine(active[i], b);
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
    for (const Triple& c : short_triples())
        if (norm_2p(combine(c, b), p) <= shortest * (1 + tolerance)) near.push_back(c);
    return near;
}

DoubleBasis normalised(DoubleBasis b, double p) {
    reduce(b);
    return scaled(b, 2 / shortest_norm(b, p));
}

}  // namespace

double norm_2p(const std::array<double, 3>& v, double p) {
    const double largest = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
    if (largest == 0) return 0;
    double sum = 0;
    for (double x : v) sum += std::pow(std::fabs(x) / largest, 2 * p);
    return largest * std::pow(sum, 1 / (2 * p));
}

double shortest_norm(const DoubleBasis& basis, double p) {
    double shortest = HUGE_VAL;
    for (const Triple& c : short_triples()) shortest = std::min(shortest, norm_2p(combine(c, basis), p));
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
        DoubleBasis b = normalised(start.basis, p);
        b = normalised(pattern_search(b, p, random, result.evaluations), p);
        SearchCandidate candidate{start.name, b, 0, {}};
        // The pattern search stops near, not at, a kink: the active set is guessed at growing
        // tolerances, and the first that Newton's method turns into a KKT point is kept.
        for (double tolerance : {1e-7, 1e-5, 1e-4, 1e-3, 1e-2}) {
            const std::optional<KktPoint> point = kkt_point(b, p, near_shortest(b, p, tolerance));
            if (point) {
                candidate.basis = normalised(point->basis, p);
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
