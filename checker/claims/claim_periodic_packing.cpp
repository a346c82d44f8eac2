// Claim kind "periodic-packing" (written by `superpack simulate --certificate`): N congruent
// convex superballs K = {|x|^(2p) + |y|^(2p) + |z|^(2p) <= 1} at an exact p >= 1/2, placed as
// c_i + R(q_i) K with exact rational centres c_i and nonzero rational quaternions q_i, and
// repeated by the lattice whose basis rows are the exact period vectors B[0], B[1], B[2], have
// pairwise disjoint interiors (a periodic packing, touching allowed), of packing density
// N V_sb(p) / |det B|. R(q) = (1/|q|^2) (the usual quaternion matrix) is exact and orthogonal.
//
// How it is verified, trusting no list in the file:
//  1. p >= 1/2, det B != 0, 1 <= N <= max_periodic_particles, every quaternion nonzero, and the
//     inputs repeat p and N.
//  2. proof.radius r bounds the circumradius of K from above (every c_i + R_i K lies in the ball
//     of radius r about c_i): r >= 1 exactly (the circumradius for p <= 1), and for p > 1
//     r^2 >= 3^(1 - 1/p) certainly in MPFI (the circumradius is 3^(1/2 - 1/(2p)), by the power
//     means). Two bodies whose centres are at least 2r apart lie in balls with disjoint interiors.
//  3. The checker enumerates every close pair itself, exactly: (i, j, k) with i <= j, k in Z^3
//     lexicographically positive when i = j, and d = c_j + k B - c_i with |d|^2 < (2r)^2. Each
//     lies in the box |k_m| <= (2r + |c_j - c_i|) |B[m+1] x B[m+2]| / |det B| (k_m is (d - c_j +
//     c_i) . column m of B^-1), bounded above in rationals; the boxes are counted, and refused
//     above max_periodic_shifts, before any is enumerated. Every close pair must be listed in
//     proof.pairs as (first i, second j, shift k).
//  4. Every listed pair (close or not) is separated: with h(u) = ||u||_s, s = 2p/(2p - 1) (the
//     support function of K; max |u_l| at p = 1/2), u_i = R_i^T n and u_j = R_j^T n, certainly
//     h(u_i) + h(u_j) <= <n, d>. Then the plane <n, x> = <n, c_i> + h(u_i) has c_i + R_i K on one
//     side and c_j + k B + R_j K on the other. h is computed as m ||u/m||_s with m = max |u_l|
//     exact, so that an axis direction gives h = m exactly, and the comparison is exact in
//     rationals whenever both norms ||u/m||_s come out as exact points (p = 1/2; touching faces).
// Pairs (i, j, k) and (j, i, -k) are one pair, and (i, i, k), (i, i, -k) one translate of the other,
// so the canonical pairs cover every two bodies of the packing.
//
// Keys read: claim.data {p, cell, particles [{center, quaternion}], packing (true)}; inputs {p,
// p_decimal, particles}; proof {kind "separating-planes", radius, pairs [{first, second, shift,
// normal}]}. NOTES.md 14.
#include <algorithm>
#include <map>
#include <tuple>
#include <vector>

#include "checker/core/limits.hpp"
#include "checker/core/render.hpp"
#include "checker/formulas/equations_lattice.hpp"
#include "checker/formulas/lattice_enumeration.hpp"
#include "checker/formulas/triple.hpp"

namespace superpack_checker {

namespace {

using Vector = RationalVector;
using Matrix = RationalMatrix;
using Quaternion = std::array<mpq_class, 4>;

struct Particle {
    Vector center;
    Quaternion quaternion;
    Matrix rotation;
};

// (first, second, shift): a canonical pair.
using PairKey = std::tuple<long, long, Triple>;

mpq_class dot(const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vector cross(const Vector& a, const Vector& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <std::size_t n>
std::array<mpq_class, n> read_rationals(Context& context, const Json& node, const std::string& path) {
    if (!node.is_array() || node.size() != n) context.malformed(path, "expected " + std::to_string(n) + " rationals");
    std::array<mpq_class, n> values;
    for (std::size_t k = 0; k < n; ++k) {
        // rational_at reads a key of an object: wrap the entry so that it is validated alike.
        const Json holder{{std::to_string(k), node[k]}};
        values[k] = context.rational_at(holder, std::to_string(k), path);
    }
    return values;
}

// R(q) for q = (w, x, y, z), exactly: orthogonal for every nonzero rational q.
Matrix rotation_of(const Quaternion& q) {
    const mpq_class &w = q[0], &x = q[1], &y = q[2], &z = q[3];
    const mpq_class s = w * w + x * x + y * y + z * z;
    Matrix r{{{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
              {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
              {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}}};
    for (auto& row : r)
        for (auto& entry : row) entry /= s;
    return r;
}

// R^T n.
Vector transposed_times(const Matrix& r, const Vector& n) {
    Vector u;
    for (int l = 0; l < 3; ++l) u[l] = r[0][l] * n[0] + r[1][l] * n[1] + r[2][l] * n[2];
    return u;
}

mpq_class ceiling(const mpq_class& q) {
    mpz_class result;
    mpz_cdiv_q(result.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
    return mpq_class(result);
}

// A rational >= sqrt(q) for q >= 0: sqrt(q) = sqrt(q S^2) / S <= isqrt(ceil(q S^2)) / S, plus 1/S
// unless that is a perfect square, with S = 2^32.
mpq_class sqrt_upper(const mpq_class& q) {
    const mpz_class scale = mpz_class(1) << 32;
    const mpq_class scaled = ceiling(q * scale * scale);
    const mpz_class c = scaled.get_num();
    mpz_class root;
    mpz_sqrt(root.get_mpz_t(), c.get_mpz_t());
    if (root * root != c) root += 1;
    mpq_class result(root, scale);
    result.canonicalize();
    return result;
}

bool is_one(const Real& x) { return mpfr_cmp_ui(x.lo(), 1) == 0 && mpfr_cmp_ui(x.hi(), 1) == 0; }
bool is_point(const Real& x) { return !mpfr_nan_p(x.lo()) && mpfr_equal_p(x.lo(), x.hi()) != 0; }

// h(u) = ||u||_s = scale * factor: scale = max |u_l| exactly, factor = ||u / scale||_s in [1, 3]
// in MPFI (the point 1 exactly for an axis direction, and for p = 1/2, where h = max |u_l|).
struct Support {
    mpq_class scale;
    Real factor;
};

Support support(const Vector& u, const mpq_class& p, mpfr_prec_t precision) {
    const mpq_class scale = std::max({abs(u[0]), abs(u[1]), abs(u[2])});  // > 0: u = R^T n, n != 0
    Support result{scale, integer(1, precision)};
    if (p == mpq_class(1, 2)) return result;
    const mpq_class s = 2 * p / (2 * p - 1);  // in (1, 2] for p >= 1, [2, oo) for p <= 1
    Vector v;
    for (int l = 0; l < 3; ++l) v[l] = abs(u[l]) / scale;
    if (s.get_den() == 1 && s <= 64) {
        // An integer exponent: sum v_l^s exactly, then its s-th root rounded outward by MPFR
        // (exact where the root is a number of `precision` bits).
        const unsigned long n = s.get_num().get_ui();
        mpq_class sum = 0;
        for (const mpq_class& x : v) {
            mpz_class num, den;
            mpz_pow_ui(num.get_mpz_t(), x.get_num_mpz_t(), n);
            mpz_pow_ui(den.get_mpz_t(), x.get_den_mpz_t(), n);
            mpq_class power(num, den);
            power.canonicalize();
            sum += power;
        }
        if (sum == 1) return result;
        const Real enclosed = rational(sum, precision);
        mpfr_t down, up;
        mpfr_inits2(precision, down, up, static_cast<mpfr_ptr>(nullptr));
        mpfr_rootn_ui(down, enclosed.lo(), n, MPFR_RNDD);
        mpfr_rootn_ui(up, enclosed.hi(), n, MPFR_RNDU);
        result.factor = outward(down, up, precision);
        mpfr_clears(down, up, static_cast<mpfr_ptr>(nullptr));
        return result;
    }
    const Real exponent = rational(s, precision);
    Real sum = integer(0, precision);
    for (const mpq_class& x : v) {
        if (x == 0) continue;
        sum = sum + (x == 1 ? integer(1, precision) : pow_abs(rational(x, precision), exponent));
    }
    if (is_one(sum)) return result;
    result.factor = pow_abs(sum, rational(1 / s, precision));
    return result;
}

// h_i + h_j <= along, certainly: exactly in rationals when both factors are points, else from
// the upper end of the MPFI sum. `shown` gets the sum as the checker knows it, for a message.
bool separated(const Support& a, const Support& b, const mpq_class& along, mpfr_prec_t precision, std::string& shown) {
    if (is_point(a.factor) && is_point(b.factor)) {
        mpq_class fa, fb;
        mpfr_get_q(fa.get_mpq_t(), a.factor.lo());
        mpfr_get_q(fb.get_mpq_t(), b.factor.lo());
        const mpq_class sum = a.scale * fa + b.scale * fb;
        shown = exact_text(sum);
        return sum <= along;
    }
    const Real sum = rational(a.scale, precision) * a.factor + rational(b.scale, precision) * b.factor;
    shown = text(sum);
    return !mpfr_nan_p(sum.hi()) && mpfr_cmp_q(sum.hi(), along.get_mpq_t()) <= 0;
}

std::string vector_words(const Vector& v) {
    return "(" + exact_text(v[0]) + ", " + exact_text(v[1]) + ", " + exact_text(v[2]) + ")";
}

std::string quaternion_words(const Quaternion& q) {
    return "(" + exact_text(q[0]) + ", " + exact_text(q[1]) + ", " + exact_text(q[2]) + ", " + exact_text(q[3]) + ")";
}

std::string pair_words(const PairKey& key) {
    return "(first " + std::to_string(std::get<0>(key)) + ", second " + std::to_string(std::get<1>(key)) + ", shift " +
           triple_text(std::get<2>(key)) + ")";
}

// c_j + k B - c_i.
Vector difference(const std::vector<Particle>& particles, const Matrix& cell, long i, long j, const Triple& k) {
    Vector d;
    for (int c = 0; c < 3; ++c)
        d[c] = particles[j].center[c] - particles[i].center[c] + k[0] * cell[0][c] + k[1] * cell[1][c] + k[2] * cell[2][c];
    return d;
}

// The boxes of lattice shifts k to enumerate, one per canonical pair of particles (i <= j), and
// how many shifts they hold in all, at most max_periodic_shifts.
struct ShiftBoxes {
    std::vector<std::array<long, 3>> bounds;  // |k_m| <= bounds[pair][m]
    mpz_class total;
};

// The box of each pair: |k_m| <= (2r + |c_j - c_i|) |B[m+1] x B[m+2]| / |det B|, which holds
// every k with |d| < 2r. A cell too thin for its radius (too many shifts) is refused.
ShiftBoxes shift_boxes(Context& context, const std::vector<Particle>& particles, const Matrix& cell, const mpq_class& det,
                       const mpq_class& radius) {
    const long n = static_cast<long>(particles.size());
    std::array<mpq_class, 3> column_norm;
    for (int m = 0; m < 3; ++m) {
        const Vector normal = cross(cell[(m + 1) % 3], cell[(m + 2) % 3]);
        column_norm[m] = sqrt_upper(dot(normal, normal) / (det * det));
    }
    const auto too_thin = [&context] {
        context.malformed("claim.data.cell", "the boxes of lattice shifts to enumerate hold more than " +
                                                 std::to_string(max_periodic_shifts) +
                                                 " shifts in all (max_periodic_shifts): the cell is too thin for its radius");
    };
    ShiftBoxes boxes_of_pairs{{}, 0};
    for (long i = 0; i < n; ++i)
        for (long j = i; j < n; ++j) {
            const Vector base = difference(particles, cell, i, j, {0, 0, 0});
            const mpq_class reach = 2 * radius + sqrt_upper(dot(base, base));
            std::array<long, 3> bound{};
            mpz_class boxes = 1;
            for (int m = 0; m < 3; ++m) {
                const mpq_class limit = reach * column_norm[m];
                mpz_class floor;
                mpz_fdiv_q(floor.get_mpz_t(), limit.get_num_mpz_t(), limit.get_den_mpz_t());
                if (floor > max_periodic_shifts) too_thin();  // before the product, which it keeps small
                boxes *= 2 * floor + 1;
                bound[m] = floor.get_si();
            }
            boxes_of_pairs.total += boxes;
            if (boxes_of_pairs.total > max_periodic_shifts) too_thin();
            boxes_of_pairs.bounds.push_back(bound);
        }
    return boxes_of_pairs;
}

// The configuration in integers, so that the enumeration compares exactly and fast: L c_i and
// L B[m], with L the common denominator of the cell and the centres.
struct ScaledConfiguration {
    mpz_class common;
    std::array<std::array<mpz_class, 3>, 3> rows;
    std::vector<std::array<mpz_class, 3>> centers;
};

// Scales the cell and the centres by L, which clears every denominator.
ScaledConfiguration scaled_configuration(const std::vector<Particle>& particles, const Matrix& cell) {
    ScaledConfiguration scaled_in{1, {}, {}};
    mpz_class& common = scaled_in.common;
    for (const Vector& row : cell)
        for (const mpq_class& x : row) mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), x.get_den_mpz_t());
    for (const Particle& particle : particles)
        for (const mpq_class& x : particle.center) mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), x.get_den_mpz_t());
    auto scaled = [&](const Vector& v) {
        std::array<mpz_class, 3> result;
        for (int c = 0; c < 3; ++c) result[c] = mpq_class(v[c] * common).get_num();  // exact: L clears the denominator
        return result;
    };
    for (int m = 0; m < 3; ++m) scaled_in.rows[m] = scaled(cell[m]);
    for (const Particle& particle : particles) scaled_in.centers.push_back(scaled(particle.center));
    return scaled_in;
}

// Every canonical pair with |d|^2 < (2r)^2, exactly (in integers: everything times the common
// denominator L of the cell and the centres), each required in `listed`. Returns how many.
long require_close_pairs(Context& context, const std::vector<Particle>& particles, const Matrix& cell, const mpq_class& det,
                         const mpq_class& radius, const std::map<PairKey, std::size_t>& listed) {
    const long n = static_cast<long>(particles.size());
    const ShiftBoxes boxes = shift_boxes(context, particles, cell, det, radius);
    const ScaledConfiguration scaled = scaled_configuration(particles, cell);
    const mpz_class& common = scaled.common;
    const auto& rows = scaled.rows;
    const auto& centers = scaled.centers;
    // |L d|^2 den(r)^2 < 4 num(r)^2 L^2.
    const mpz_class limit = 4 * radius.get_num() * radius.get_num() * common * common;
    const mpz_class factor = radius.get_den() * radius.get_den();

    const auto squared_distance = [&common](const mpz_class& norm) {
        mpq_class result(norm, common * common);
        result.canonicalize();
        return result;
    };
    long found = 0;
    std::size_t pair = 0;
    std::array<mpz_class, 3> da, dab, d;
    mpz_class norm, term;
    for (long i = 0; i < n; ++i)
        for (long j = i; j < n; ++j, ++pair) {
            const std::array<long, 3>& bound = boxes.bounds[pair];
            for (long a = -bound[0]; a <= bound[0]; ++a) {
                for (int c = 0; c < 3; ++c) da[c] = centers[j][c] - centers[i][c] + a * rows[0][c];
                for (long b = -bound[1]; b <= bound[1]; ++b) {
                    for (int c = 0; c < 3; ++c) {
                        dab[c] = da[c] + b * rows[1][c];
                        d[c] = dab[c] - bound[2] * rows[2][c];
                    }
                    for (long e = -bound[2]; e <= bound[2]; ++e) {
                        const Triple k{a, b, e};
                        if (i != j || canonical(k)) {
                            mpz_mul(norm.get_mpz_t(), d[0].get_mpz_t(), d[0].get_mpz_t());
                            mpz_addmul(norm.get_mpz_t(), d[1].get_mpz_t(), d[1].get_mpz_t());
                            mpz_addmul(norm.get_mpz_t(), d[2].get_mpz_t(), d[2].get_mpz_t());
                            mpz_mul(term.get_mpz_t(), norm.get_mpz_t(), factor.get_mpz_t());
                            if (term < limit) {
                                const PairKey key{i, j, k};
                                context.require(listed.count(key) != 0, "proof.pairs",
                                                "the pair " + pair_words(key) + " is missing: its centres are " +
                                                    exact_text(squared_distance(norm)) +
                                                    " apart squared, less than (2r)^2 = " + exact_text(4 * radius * radius));
                                ++found;
                            }
                        }
                        for (int c = 0; c < 3; ++c) d[c] += rows[2][c];
                    }
                }
            }
        }
    context.count_steps(mpz_class(boxes.total).get_si());
    return found;
}

// The particles of claim.data: each a centre and a nonzero quaternion (its rotation with it);
// from 1 to max_periodic_particles of them.
std::vector<Particle> read_particles(Context& context, const Json& data) {
    const Json& list = context.member(data, "particles", "claim.data");
    if (!list.is_array() || list.empty() || list.size() > max_periodic_particles)
        context.malformed("claim.data.particles", "expected from 1 to " + std::to_string(max_periodic_particles) +
                                                      " particles (max_periodic_particles)");
    std::vector<Particle> particles;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = "claim.data.particles[" + std::to_string(i) + "]";
        Particle particle;
        particle.center = read_rationals<3>(context, context.member(list[i], "center", path), path + ".center");
        particle.quaternion = read_rationals<4>(context, context.member(list[i], "quaternion", path), path + ".quaternion");
        const Quaternion& q = particle.quaternion;
        context.require(q[0] != 0 || q[1] != 0 || q[2] != 0 || q[3] != 0, path + ".quaternion", "the zero quaternion is no rotation");
        particle.rotation = rotation_of(q);
        particles.push_back(particle);
    }
    return particles;
}

// The claim is a packing, of as many particles as the inputs name.
void check_packing_and_count(Context& context, const Json& data, const Json& inputs, std::size_t n) {
    const Json& packing = context.member(data, "packing", "claim.data");
    if (!packing.is_boolean()) context.malformed("claim.data.packing", "expected true or false");
    context.require(packing.get<bool>(), "claim.data.packing", "this kind certifies packings only");
    const long count = read_integer(context, context.member(inputs, "particles", "inputs"), "inputs.particles", 1,
                                    static_cast<long>(max_periodic_particles), "max_periodic_particles");
    context.require(count == static_cast<long>(n), "inputs.particles", "the input count " + std::to_string(count) +
                                                                           " differs from the claim's " + std::to_string(n) + " particles");
}

// The radius r of proof.radius: at least the circumradius of K (1 for p <= 1, 3^((1 - 1/p)/2)
// above), so that two bodies whose centres are 2r apart or more cannot meet.
mpq_class read_radius(Context& context, const Json& proof, const mpq_class& p) {
    const mpfr_prec_t precision = context.precision();
    context.current_step = "proof.radius";
    const mpq_class radius = context.rational_at(proof, "radius", "proof");
    context.require(radius >= 1, "proof.radius", "r = " + exact_text(radius) + " < 1, below the circumradius of K");
    if (p > 1) {
        const Real squared = pow_abs(integer(3, precision), rational(1 - 1 / p, precision));
        const mpq_class r2 = radius * radius;
        context.require(!mpfr_nan_p(squared.hi()) && mpfr_cmp_q(squared.hi(), r2.get_mpq_t()) <= 0, "proof.radius",
                        "r^2 = " + exact_text(r2) + " is not certainly >= 3^(1 - 1/p) in " + text(squared) +
                            ", the squared circumradius of K");
    }
    return radius;
}

// The pairs of proof.pairs, in order: each with its separating plane's normal.
struct ListedPairs {
    std::map<PairKey, std::size_t> listed;  // pair -> its index
    std::vector<PairKey> keys;
    std::vector<Vector> normals;
};

// The listed pairs, canonical and once each, of particles 0..n-1.
ListedPairs read_pairs(Context& context, const Json& proof, std::size_t n) {
    const Json& pairs = context.member(proof, "pairs", "proof");
    if (!pairs.is_array()) context.malformed("proof.pairs", "expected an array");
    ListedPairs read;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const std::string path = "proof.pairs[" + std::to_string(k) + "]";
        const Json& entry = pairs[k];
        const long last = static_cast<long>(n) - 1;
        const long first = read_integer(context, context.member(entry, "first", path), path + ".first", 0, last);
        const long second = read_integer(context, context.member(entry, "second", path), path + ".second", 0, last);
        const Triple shift = read_triple(context, context.member(entry, "shift", path), path + ".shift");
        const Vector normal = read_rationals<3>(context, context.member(entry, "normal", path), path + ".normal");
        if (first > second) context.malformed(path, "not canonical: first > second (the pair is (second, first) with shift -k)");
        if (first == second && !canonical(shift))
            context.malformed(path + ".shift", "not canonical: with first = second the shift must be lexicographically positive");
        const PairKey key{first, second, shift};
        if (!read.listed.emplace(key, k).second) context.malformed(path, "the pair " + pair_words(key) + " is listed twice");
        read.keys.push_back(key);
        read.normals.push_back(normal);
    }
    return read;
}

// Every listed pair separated by its plane: h(R_i^T n) + h(R_j^T n) <= <n, d>, certainly.
void require_planes_separate(Context& context, const ListedPairs& pairs, const std::vector<Particle>& particles,
                             const Matrix& cell, const mpq_class& p) {
    const mpfr_prec_t precision = context.precision();
    for (std::size_t k = 0; k < pairs.keys.size(); ++k) {
        const std::string path = "proof.pairs[" + std::to_string(k) + "]";
        context.current_step = path;
        const auto& [i, j, shift] = pairs.keys[k];
        const Vector& normal = pairs.normals[k];
        context.require(normal[0] != 0 || normal[1] != 0 || normal[2] != 0, path + ".normal", "the zero vector is no normal");
        const Vector d = difference(particles, cell, i, j, shift);
        const mpq_class along = dot(normal, d);
        const Support a = support(transposed_times(particles[i].rotation, normal), p, precision);
        const Support b = support(transposed_times(particles[j].rotation, normal), p, precision);
        std::string shown;
        context.require(separated(a, b, along, precision, shown), path + ".normal",
                        "the plane does not certainly separate the pair " + pair_words(pairs.keys[k]) +
                            ": h(R_i^T n) + h(R_j^T n) = " + shown + " exceeds <n, d> = " + exact_text(along) + " (d = " +
                            vector_words(d) + ")");
    }
}

std::string check_periodic_packing(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const Json& proof = context.member(document, "proof", "");
    context.current_step = "claim.data";

    // 1. The configuration.
    const mpq_class p = context.rational_at(data, "p", "claim.data");
    context.require(context.rational_at(inputs, "p", "inputs") == p, "inputs.p", "the input p differs from the claim's");
    context.require(p >= mpq_class(1, 2), "claim.data.p", "the separating-plane test needs p >= 1/2 (a convex superball)");
    const Matrix cell = read_basis(context, context.member(data, "cell", "claim.data"), "claim.data.cell");
    const mpq_class det = dot(cell[0], cross(cell[1], cell[2]));
    context.require(det != 0, "claim.data.cell", "the cell is singular (det B = 0): its rows span no lattice");
    const std::vector<Particle> particles = read_particles(context, data);
    const std::size_t n = particles.size();
    check_packing_and_count(context, data, inputs, n);

    // 2. The radius, and the listed pairs.
    if (context.string_at(proof, "kind", "proof") != "separating-planes") context.malformed("proof.kind", "expected \"separating-planes\"");
    const mpq_class radius = read_radius(context, proof, p);
    const ListedPairs pairs = read_pairs(context, proof, n);

    // 3. Completeness: the checker's own close pairs.
    context.current_step = "proof.pairs";
    const long close = require_close_pairs(context, particles, cell, det, radius, pairs.listed);

    // 4. Every listed pair separated by its plane.
    require_planes_separate(context, pairs, particles, cell, p);
    check_p_decimal(context, inputs, p);  // after the proof, which names a wrong p first

    // 5. The sentence.
    std::string placed;
    for (std::size_t i = 0; i < n; ++i)
        placed += std::string(i ? "; " : "") + "c_" + std::to_string(i) + " = " + vector_words(particles[i].center) + ", q_" +
                  std::to_string(i) + " = " + quaternion_words(particles[i].quaternion);
    return "The periodic arrangement of N = " + std::to_string(n) + (n == 1 ? " superball" : " superballs") +
           " c_i + R(q_i) K, K = {|x|^(2p) + |y|^(2p) + |z|^(2p) <= 1} at p = " + exact_text(p) +
           " and R(q) the rotation of the quaternion q, with " + placed + ", repeated by the lattice with basis rows " +
           basis_words(cell) +
           ", is a packing: its bodies have pairwise disjoint interiors (every two whose centres are closer than 2r, r = " +
           exact_text(radius) + " >= the circumradius of K, are separated by a plane; " + std::to_string(close) +
           (close == 1 ? " such pair" : " such pairs") +
           " up to translation), of packing density N V_sb(p) / |det B| with |det B| = " + exact_text(abs(det)) + ".";
}

const ClaimKindRegistration registration("periodic-packing", check_periodic_packing);

}  // namespace

}  // namespace superpack_checker
