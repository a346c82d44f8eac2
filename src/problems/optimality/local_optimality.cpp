#include "superpack/problems/optimality/local_optimality.hpp"

#include <algorithm>
#include <cmath>

#include "superpack/arith/contract.hpp"
#include "superpack/solve/krawczyk.hpp"

namespace superpack {

namespace {

// sign(u) |u|^e, with the derivative e |u|^(e-1) du of the whole (not of u times |u|^(e-1),
// whose product rule leaves an unbounded term at u = 0 although the function is C^1 for e > 1:
// C0's contact (0, 0, 2) has two zero coordinates).
template <class I>
I signed_power(const I& u, const I& e) {
    return pow_signed(u, e);
}
template <class I>
Jet<I> signed_power(const Jet<I>& u, const I& e) {
    return {pow_signed(u.value, e), e * pow_abs(u.value, e - field_of(e).integer(1)) * u.derivative};
}

// Both varying (the derivative in p of the KKT system, whose exponent is 2p - 1): the term
// sign(u) |u|^e log|u| de is added only when de is not exactly 0, as in pow_abs (jet.hpp).
template <class I>
Jet<I> signed_power(const Jet<I>& u, const Jet<I>& e) {
    Jet<I> result = signed_power(u, e.value);
    if (!(contains_zero(e.derivative) && width_upper(e.derivative) == 0.0))
        result.derivative = result.derivative + result.value * log(abs(u.value)) * e.derivative;
    return result;
}

}  // namespace

template <class T, class P>
std::vector<T> kkt_equations(const std::vector<T>& x, const std::vector<Coefficients>& active, const P& p) {
    const auto field = field_of(p);
    const P two_p = field.integer(2) * p;
    const P power = two_p - field.integer(1);
    auto entry = [&](int k, int j) -> const T& { return x[3 * k + j]; };
    std::vector<T> equations;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) {
            const int k1 = (k + 1) % 3, k2 = (k + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            equations.push_back(entry(k1, j1) * entry(k2, j2) - entry(k1, j2) * entry(k2, j1));
        }
    for (std::size_t i = 0; i < active.size(); ++i) {
        const Coefficients& c = active[i];
        std::vector<T> v;
        for (int j = 0; j < 3; ++j)
            v.push_back(field.integer(c[0]) * entry(0, j) + field.integer(c[1]) * entry(1, j) + field.integer(c[2]) * entry(2, j));
        const T sum = pow_abs(v[0], two_p) + pow_abs(v[1], two_p) + pow_abs(v[2], two_p);
        const T norm = pow_nonneg(sum, field.integer(1) / two_p);
        const T& mu = x[9 + i];
        for (int j = 0; j < 3; ++j) {
            const T u = v[j] / norm;
            const T slope = signed_power(u, power);  // sign(u) |u|^(2p-1)
            for (int k = 0; k < 3; ++k)
                if (c[k] != 0) equations[3 * k + j] = equations[3 * k + j] - field.integer(c[k]) * mu * slope;
        }
        equations.push_back(norm - field.integer(2));
    }
    return equations;
}

template <class I>
bool certainly_positive_definite(const std::vector<std::vector<I>>& m) {
    const std::size_t n = m.size();
    std::vector<std::vector<I>> l(n, std::vector<I>(n, m[0][0] - m[0][0]));
    for (std::size_t j = 0; j < n; ++j) {
        I pivot = m[j][j];
        for (std::size_t k = 0; k < j; ++k) pivot = pivot - square(l[j][k]);
        if (!certainly_positive(pivot)) return false;
        l[j][j] = sqrt(pivot);
        for (std::size_t i = j + 1; i < n; ++i) {
            I sum = m[i][j];
            for (std::size_t k = 0; k < j; ++k) sum = sum - l[i][k] * l[j][k];
            l[i][j] = sum / l[j][j];
        }
    }
    return true;
}

template bool certainly_positive_definite(const std::vector<std::vector<DInterval>>&);
template bool certainly_positive_definite(const std::vector<std::vector<Ball>>&);

template <class I>
KrawczykResult<I> isolate_kkt_point(const KktPoint& guess, const std::vector<Coefficients>& active, const I& p) {
    const auto field = field_of(p);
    std::vector<I> box;
    for (std::size_t k = 0; k < 9 + active.size(); ++k) {
        const double x = k < 9 ? guess.basis[k / 3][k % 3] : guess.multipliers[k - 9];
        const double radius = 1e-9 * std::max(1.0, std::fabs(x));
        box.push_back(from_doubles(field.integer(0), x - radius, x + radius));
    }
    auto equations = [&](const auto& x) { return kkt_equations(x, active, p); };
    const double target = std::ldexp(1.0, -static_cast<int>(field.bits()) + 12);
    return krawczyk_isolate(equations, box, target, 40);
}

// Every step but the domain checks of certify_local_optimum.
template <class I>
LocalOptimum<I> certify_smooth_local_optimum(const DoubleBasis& guess, const std::vector<Coefficients>& contacts, const I& p);

template <class I>
LocalOptimum<I> certify_local_optimum(const DoubleBasis& guess, const std::vector<Coefficients>& contacts, const I& p) {
    LocalOptimum<I> result;
    const auto field = field_of(p);
    // The second-order conditions need twice differentiable constraints: the norm is piecewise
    // linear at p = 1/2 (an octahedron: Betke and Henk's polyhedral setting, NOTES 11.5.1).
    if (!certainly_less(field.rational(Rational(1, 2)), p)) {
        result.reason = "not decided at p = 1/2: the norm is not differentiable there (a polytope)";
        return result;
    }
    Contracted<LocalOptimum<I>> smooth = within_contract([&] { return certify_smooth_local_optimum(guess, contacts, p); });
    if (smooth.status == ContractStatus::held) return std::move(*smooth.value);
    result.reason = smooth.reason();
    return result;
}

template <class I>
LocalOptimum<I> certify_smooth_local_optimum(const DoubleBasis& guess, const std::vector<Coefficients>& contacts, const I& p) {
    LocalOptimum<I> result;
    const auto field = field_of(p);
    // The system minimises det B, so the basis must have det > 0: otherwise b3 -> -b3, which
    // maps a triple (a, b, c) to (a, b, -c).
    DoubleBasis oriented = guess;
    const bool flip = determinant(guess) < 0;
    if (flip)
        for (double& x : oriented[2]) x = -x;
    std::vector<Coefficients> active;
    for (Coefficients c : contacts) {
        if (flip) c[2] = -c[2];
        if (std::find(active.begin(), active.end(), representative(c)) == active.end()) active.push_back(representative(c));
    }
    const std::optional<KktPoint> point = kkt_point(oriented, mid_double(p), active);
    if (!point) {
        result.reason = "Newton's method found no KKT point with positive multipliers for these " +
                        std::to_string(active.size()) + " contact pairs (at p = 1 rotations make every critical lattice "
                        "non-isolated)";
        return result;
    }
    const std::size_t n = 9 + active.size();
    auto equations = [&](const auto& x) { return kkt_equations(x, active, p); };
    const KrawczykResult<I> root = isolate_kkt_point(*point, active, p);
    result.contacts = active;
    result.search_box = root.initial_box;
    if (root.status != RootStatus::unique) {
        result.reason = "Krawczyk did not prove a unique KKT point near the guess (" + root.reason +
                        "); at p = 1 rotations make the critical lattice non-isolated";
        return result;
    }
    for (std::size_t i = 0; i < active.size(); ++i) {
        result.multipliers.push_back(root.box[9 + i]);
        if (!certainly_positive(root.box[9 + i])) {
            result.reason = "a multiplier is not certainly positive: the contact may not be needed";
            return result;
        }
    }
    // H (rows 0..8) and A (rows 9..) over the root box, one column per entry of B.
    std::vector<std::vector<I>> jacobian(n, std::vector<I>(9, field.integer(0)));
    for (std::size_t j = 0; j < 9; ++j) {
        std::vector<Jet<I>> seeded;
        for (std::size_t k = 0; k < n; ++k) seeded.push_back(k == j ? variable(root.box[k]) : constant(root.box[k]));
        const std::vector<Jet<I>> column = equations(seeded);
        for (std::size_t i = 0; i < n; ++i) jacobian[i][j] = column[i].derivative;
    }
    for (const double rho : {0.0, 1.0, 10.0, 100.0, 1000.0, 10000.0}) {
        std::vector<std::vector<I>> m(9, std::vector<I>(9, field.integer(0)));
        for (std::size_t a = 0; a < 9; ++a)
            for (std::size_t b = 0; b <= a; ++b) {
                I entry = jacobian[a][b];
                for (std::size_t i = 9; i < n; ++i)
                    entry = entry + from_doubles(field.integer(0), rho, rho) * jacobian[i][a] * jacobian[i][b];
                m[a][b] = entry;
            }
        if (certainly_positive_definite(m)) {
            result.rho = rho;
            break;
        }
        if (rho == 10000.0) {
            result.reason = "the second-order condition was not certified (H + rho A^T A not proved positive definite "
                            "for rho up to 10^4)";
            return result;
        }
    }
    const std::vector<I>& x = root.box;
    const Basis<I> basis{{{x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}}};
    const LatticeCheck<I> check = check_lattice(basis, p, [&](const Coefficients& c) {
        return std::find(active.begin(), active.end(), representative(c)) != active.end();
    });
    result.basis = basis;
    result.phi = enclose_ball_volume(p, 3) / abs(determinant(basis));
    result.check = check;
    if (check.verdict != Outcome::proved || check.contacts() != 2 * active.size()) {
        result.reason = "the critical lattice's box is not proved admissible with exactly these contacts (" + check.reason + ")";
        return result;
    }
    result.verdict = Outcome::proved;
    result.reason = "a strict local minimiser of |det| among nearby admissible lattices: the KKT point is unique in its box "
                    "(Krawczyk), its " + std::to_string(active.size()) +
                    " multipliers are positive, H + " + std::to_string(static_cast<long>(result.rho)) +
                    " A^T A is positive definite (interval Cholesky), and every other lattice vector is longer than 2";
    return result;
}

template std::vector<DInterval> kkt_equations(const std::vector<DInterval>&, const std::vector<Coefficients>&, const DInterval&);
template std::vector<Ball> kkt_equations(const std::vector<Ball>&, const std::vector<Coefficients>&, const Ball&);
template std::vector<Jet<DInterval>> kkt_equations(const std::vector<Jet<DInterval>>&, const std::vector<Coefficients>&,
                                                   const DInterval&);
template std::vector<Jet<Ball>> kkt_equations(const std::vector<Jet<Ball>>&, const std::vector<Coefficients>&, const Ball&);
template std::vector<Jet<DInterval>> kkt_equations(const std::vector<Jet<DInterval>>&, const std::vector<Coefficients>&,
                                                   const Jet<DInterval>&);
template KrawczykResult<DInterval> isolate_kkt_point(const KktPoint&, const std::vector<Coefficients>&, const DInterval&);
template KrawczykResult<Ball> isolate_kkt_point(const KktPoint&, const std::vector<Coefficients>&, const Ball&);
template LocalOptimum<DInterval> certify_local_optimum(const DoubleBasis&, const std::vector<Coefficients>&, const DInterval&);
template LocalOptimum<Ball> certify_local_optimum(const DoubleBasis&, const std::vector<Coefficients>&, const Ball&);

}  // namespace superpack
