#include "superpack/problems/periodic/periodic_packing.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "superpack/geometry/body.hpp"

namespace superpack {

Basis<Rational> rotation_of(const std::array<Rational, 4>& q) {
    const Rational &w = q[0], &x = q[1], &y = q[2], &z = q[3];
    const Rational s = w * w + x * x + y * y + z * z;
    if (s == 0) throw InputError("a zero quaternion is no rotation");
    Basis<Rational> r{{{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                       {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                       {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}}};
    for (auto& row : r)
        for (auto& entry : row) entry /= s;
    return r;
}

Rational dyadic_near(double x, int bits) {
    if (!std::isfinite(x)) throw std::invalid_argument("dyadic_near: not a finite number");
    mpz_class scale;
    mpz_ui_pow_ui(scale.get_mpz_t(), 2, static_cast<unsigned long>(bits));
    // x * 2^bits is exact in binary64 (a power of two); its nearest integer, exactly.
    const double scaled = std::nearbyint(std::ldexp(x, bits));
    mpz_class steps;
    mpz_set_d(steps.get_mpz_t(), scaled);
    Rational result(steps, scale);
    result.canonicalize();  // GMP compares rationals by representation: lowest terms always
    return result;
}

namespace {

double to_double(const Rational& x) { return x.get_d(); }

RationalVector3 shifted_difference(const PeriodicPacking& packing, std::size_t i, std::size_t j, const Shift& k) {
    RationalVector3 d;
    for (int c = 0; c < 3; ++c)
        d[c] = packing.centers[j][c] - packing.centers[i][c] + k[0] * packing.cell[0][c] + k[1] * packing.cell[1][c] +
               k[2] * packing.cell[2][c];
    return d;
}

Rational dot(const RationalVector3& a, const RationalVector3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

bool lexicographically_positive(const Shift& k) {
    for (int c = 0; c < 3; ++c)
        if (k[c] != 0) return k[c] > 0;
    return false;
}

// Every canonical pair with centres closer than 2r, exactly. The box of shifts comes from
// k = (d - (c_j - c_i)) B^-1: |k_m| <= (2r + |c_j - c_i|) ||column m of B^-1||, bounded in
// floating point with room to spare (the exact filter decides, and the checker enumerates on
// its own).
std::vector<std::pair<PairSeparation, RationalVector3>> close_pairs(const PeriodicPacking& packing, const Rational& radius) {
    const Rational reach = 4 * radius * radius;
    const Basis<Rational>& b = packing.cell;
    const Rational det = determinant(b);
    // Columns of B^-1 are the cofactor rows divided by det.
    std::array<double, 3> column_norm{};
    for (int m = 0; m < 3; ++m) {
        const int u = (m + 1) % 3, v = (m + 2) % 3;
        double sum = 0;
        for (int l = 0; l < 3; ++l) {
            const int s = (l + 1) % 3, t = (l + 2) % 3;
            // Entry (l, m) of B^-1: the cofactor of b[m][l] over det.
            const Rational cofactor = b[u][s] * b[v][t] - b[u][t] * b[v][s];
            const double entry = to_double(cofactor / det);
            sum += entry * entry;
        }
        column_norm[m] = std::sqrt(sum);
    }
    std::vector<std::pair<PairSeparation, RationalVector3>> result;
    const std::size_t n = packing.centers.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i; j < n; ++j) {
            const RationalVector3 base = shifted_difference(packing, i, j, {0, 0, 0});
            const double length = std::sqrt(to_double(dot(base, base)));
            std::array<long, 3> bound{};
            double boxes = 1;
            for (int m = 0; m < 3; ++m) {
                bound[m] = static_cast<long>(std::floor((2 * to_double(radius) + length) * column_norm[m] * (1 + 1e-9))) + 1;
                boxes *= 2.0 * bound[m] + 1;
            }
            if (boxes > max_shifts_per_pair)
                throw InputError("periodic packing: the cell is too thin (more than " + std::to_string(max_shifts_per_pair) +
                                 " shifts per pair)");
            for (long a = -bound[0]; a <= bound[0]; ++a)
                for (long c = -bound[1]; c <= bound[1]; ++c)
                    for (long e = -bound[2]; e <= bound[2]; ++e) {
                        const Shift k{int(a), int(c), int(e)};
                        if (i == j && !lexicographically_positive(k)) continue;
                        const RationalVector3 d = shifted_difference(packing, i, j, k);
                        if (dot(d, d) >= reach) continue;
                        PairSeparation pair;
                        pair.first = i;
                        pair.second = j;
                        pair.shift = k;
                        result.push_back({pair, d});
                    }
        }
    return result;
}

// A rational r with r >= the circumradius of K (1 for p <= 1, 3^(1/2 - 1/(2p)) above, by the
// power means), proved in intervals; sqrt(3) bounds it for every p.
template <class Field>
Rational circumradius_bound(const Rational& p, const Field& field) {
    if (p <= 1) return 1;
    const Rational guess = dyadic_near(std::pow(3.0, 0.5 - 0.5 / to_double(p)) * (1 + 1e-9), 40) + Rational(1, 1L << 40);
    const auto squared = pow_nonneg(field.integer(3), field.rational(1 - 1 / p));
    if (certainly_less(squared, field.rational(guess * guess))) return guess;
    return Rational(17320509, 10000000);
}

// The input's checks, each with its InputError (a step of its own: certify reads as check,
// separate, scale).
void check_periodic_input(const PeriodicPacking& input) {
    if (input.p < Rational(1, 2)) throw InputError("periodic packing: p = " + decimal_or_fraction_text(input.p) + " is below 1/2 (not convex)");
    if (input.centers.empty() || input.centers.size() != input.quaternions.size())
        throw InputError("periodic packing: needs as many quaternions as centres, and at least one");
    if (input.centers.size() > max_periodic_particles)
        throw InputError("periodic packing: at most " + std::to_string(max_periodic_particles) + " particles");
    if (determinant(input.cell) == 0) throw InputError("periodic packing: the cell is singular");
}

// The support function of the rotated body in direction n: h(R^T n) (its own function: each
// pair's separation needs it for both bodies and both normals).
template <class Field>
typename Field::Interval rotated_support(const Superball& body, const Basis<Rational>& rotation, const RationalVector3& n,
                                         const Field& field) {
    std::vector<typename Field::Interval> u;
    for (int c = 0; c < 3; ++c) u.push_back(field.rational(rotation[0][c] * n[0] + rotation[1][c] * n[1] + rotation[2][c] * n[2]));
    return support_function(body, u);
}

// Sets pair.normal for the close pair with centre difference d: of the guess and the centre
// line (which always works once scaled enough), the first that proves the pair, else the one
// that needs the smaller scale; returns that scale, nothing when the pair is proved (or when
// neither normal gives a finite ratio: then pair.normal stays zero). One pair's step of certify.
template <class Field>
std::optional<Rational> separate_pair(PairSeparation& pair, const RationalVector3& d, const NormalGuess& guess,
                                      const std::vector<Basis<Rational>>& rotations, const Superball& body, const Field& field) {
    using I = typename Field::Interval;
    const std::array<double, 3> approximate{to_double(d[0]), to_double(d[1]), to_double(d[2])};
    const std::array<double, 3> n = guess ? guess(pair.first, pair.second, approximate) : approximate;
    RationalVector3 guessed;
    for (int c = 0; c < 3; ++c) guessed[c] = std::isfinite(n[c]) ? dyadic_near(n[c], 40) : Rational(0);
    std::optional<Rational> best_factor;
    for (const RationalVector3& normal : {guessed, d}) {
        const Rational along = dot(normal, d);
        if (along <= 0) continue;  // this normal faces away
        const I reach = rotated_support(body, rotations[pair.first], normal, field) +
                        rotated_support(body, rotations[pair.second], normal, field);
        if (certainly_nonnegative(field.rational(along) - reach)) {
            pair.normal = normal;
            best_factor.reset();
            break;
        }
        const double ratio = mid_double(upper_point(reach / field.rational(along)));
        if (!std::isfinite(ratio)) continue;
        const Rational factor = dyadic_near(ratio, 40) + Rational(1, 1L << 30);
        if (!best_factor || factor < *best_factor) {
            best_factor = factor;
            pair.normal = normal;
        }
    }
    return best_factor;
}

// The certificate once every pair is separated: the density at the final scale (a step of
// its own: the proved ending of certify).
template <class Field>
void record_proved(PeriodicCertificate<typename Field::Interval>& result, const PeriodicPacking& input, const Field& field) {
    using I = typename Field::Interval;
    result.status = Outcome::proved;
    result.determinant = abs(determinant(result.packing.cell));
    const I volume = enclose_superball_volume(input.p, field);
    result.phi = field.integer(static_cast<long>(input.centers.size())) * volume / field.rational(result.determinant);
    result.reason = result.scale == 1 ? "every pair is separated by a plane" :
                    "every pair is separated by a plane once the configuration is scaled by " + rational_text(result.scale);
}

// The configuration scaled by `factor` about the origin: cell and centres (a step of its own:
// the round that did not prove every pair ends with it).
template <class I>
void scale_packing(PeriodicCertificate<I>& result, const Rational& factor) {
    result.scale *= factor;
    for (auto& row : result.packing.cell)
        for (auto& entry : row) entry *= factor;
    for (auto& center : result.packing.centers)
        for (auto& entry : center) entry *= factor;
}

template <class Field>
PeriodicCertificate<typename Field::Interval> certify(const PeriodicPacking& input, const NormalGuess& guess, const Field& field) {
    using I = typename Field::Interval;
    check_periodic_input(input);
    const Superball body = make_superball(3, input.p);
    std::vector<Basis<Rational>> rotations;
    for (const auto& q : input.quaternions) rotations.push_back(rotation_of(q));

    PeriodicCertificate<I> result;
    result.packing = input;
    result.radius = circumradius_bound(input.p, field);
    // Scaling by s >= 1 only moves centres apart, so a few rounds settle it; the bound keeps a
    // numerically stubborn case from looping.
    for (int round = 0; round < 4; ++round) {
        result.pairs.clear();
        Rational needed = 1;
        bool all_proved = true;
        for (auto& [pair, d] : close_pairs(result.packing, result.radius)) {
            const std::optional<Rational> best_factor = separate_pair(pair, d, guess, rotations, body, field);
            if (best_factor) {
                all_proved = false;
                if (*best_factor > needed) needed = *best_factor;
            } else if (pair.normal[0] == 0 && pair.normal[1] == 0 && pair.normal[2] == 0) {
                result.reason = "a support function is not enclosed finitely at this precision";
                return result;
            }
            result.pairs.push_back(pair);
        }
        if (all_proved) {
            record_proved(result, input, field);
            return result;
        }
        scale_packing(result, needed);
    }
    result.reason = "some pair is not separated even after scaling four times (the support functions are too wide at this precision)";
    return result;
}

}  // namespace

PeriodicCertificate<DInterval> certify_periodic_packing(const PeriodicPacking& packing, const NormalGuess& guess, const DoubleField& field) {
    return certify(packing, guess, field);
}
PeriodicCertificate<Ball> certify_periodic_packing(const PeriodicPacking& packing, const NormalGuess& guess, const BallField& field) {
    return certify(packing, guess, field);
}

}  // namespace superpack
