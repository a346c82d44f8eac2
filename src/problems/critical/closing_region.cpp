#include "superpack/problems/critical/closing_region.hpp"

#include <algorithm>
#include <cmath>

#include "superpack/arith/contract.hpp"
#include "superpack/solve/krawczyk.hpp"

namespace superpack {

namespace {

// Whether the Hessian of the augmented Lagrangian is positive definite on the whole region:
// the Jacobian of its gradient, one column per entry of B, over the region and the
// multipliers' box (the true mu* lies in it, so the true Hessian at every point of the region
// is one of the symmetric matrices whose lower triangle lies in the enclosure).
template <class I>
bool hessian_positive_definite(const ClosingRegion<I>& region, const I& p, double rho) {
    const auto field = field_of(p);
    const I two_p = field.integer(2) * p;
    const I weight = from_doubles(field.integer(0), rho, rho);
    auto gradient = [&](const auto& entries) {
        using T = std::decay_t<decltype(entries[0])>;
        std::vector<T> x(entries.begin(), entries.end());
        const Basis<T> basis{{{x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}}};
        for (std::size_t i = 0; i < region.contacts.size(); ++i) {
            std::array<T, 3> v;
            for (int j = 0; j < 3; ++j) {
                T sum = constant_like(x[0], 0);
                for (int k = 0; k < 3; ++k) sum = sum + constant_like(x[0], region.contacts[i][k]) * basis[k][j];
                v[j] = sum;
            }
            const T power = pow_abs(v[0], two_p) + pow_abs(v[1], two_p) + pow_abs(v[2], two_p);
            const T norm = pow_nonneg(power, field.integer(1) / two_p);
            // grad of rho/2 (n - 2)^2 is rho (n - 2) grad n: a shift of the multiplier.
            x.push_back(constant_like(x[0], 0) + region.multipliers[i] - weight * (norm - field.integer(2)));
        }
        std::vector<T> rows = kkt_equations(x, region.contacts, p);
        rows.resize(9);
        return rows;
    };
    std::vector<I> entries;
    for (const auto& row : region.region)
        for (const I& entry : row) entries.push_back(entry);
    std::vector<std::vector<I>> hessian(9, std::vector<I>(9, field.integer(0)));
    for (std::size_t b = 0; b < 9; ++b) {
        std::vector<Jet<I>> seeded;
        for (std::size_t k = 0; k < 9; ++k) seeded.push_back(k == b ? variable(entries[k]) : constant(entries[k]));
        const std::vector<Jet<I>> column = gradient(seeded);
        for (std::size_t a = 0; a < 9; ++a) {
            if (!bounded(column[a].derivative)) return false;
            hessian[a][b] = column[a].derivative;
        }
    }
    return certainly_positive_definite(hessian);
}

}  // namespace

template <class I>
ClosingRegion<I> certify_closing_region(const LocalOptimum<I>& optimum, const I& p, double first_radius, int attempts) {
    ClosingRegion<I> result;
    const auto field = field_of(p);
    result.determinant = field.integer(0);
    if (optimum.verdict != Outcome::proved || !optimum.basis) {
        result.reason = "the critical lattice is not a certified local optimum (" + optimum.reason + ")";
        return result;
    }
    result.contacts = optimum.contacts;
    // The lemma needs grad L(B*) = 0 for the multipliers used: the KKT point is proved again in the
    // box of the given basis and multipliers (Krawczyk), so that a region is never built on
    // multipliers that are not the critical lattice's.
    std::vector<I> box;
    for (const auto& row : *optimum.basis)
        for (const I& entry : row) box.push_back(entry);
    box.insert(box.end(), optimum.multipliers.begin(), optimum.multipliers.end());
    // Widened by a relative 1e-10 (epsilon inflation): Krawczyk needs room to map the box into
    // its interior, which a root box refined to the last bits does not leave.
    for (I& entry : box) {
        const double widening = 1e-10 * std::max(1.0, std::fabs(mid_double(entry)));
        entry = entry + from_doubles(field.integer(0), -widening, widening);
    }
    auto equations = [&](const auto& x) { return kkt_equations(x, optimum.contacts, p); };
    const KrawczykResult<I> root = krawczyk_isolate(equations, box, 0.0, 3);
    if (root.status != RootStatus::unique) {
        result.reason = "Krawczyk did not prove the KKT point in the box of the given basis and multipliers (" + root.reason + ")";
        return result;
    }
    const std::vector<I>& x = root.box;
    result.center = {{{x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}}};
    result.multipliers.assign(x.begin() + 9, x.end());
    for (const I& mu : result.multipliers)
        if (!certainly_positive(mu)) {
            result.reason = "a multiplier is not certainly positive";
            return result;
        }
    result.determinant = determinant(result.center);
    if (!certainly_positive(result.determinant)) {
        result.reason = "det B* is not certainly positive";
        return result;
    }
    double radius = first_radius;
    const Contracted<bool> proved = within_contract([&] {
        for (int attempt = 0; attempt < attempts; ++attempt, radius /= 4) {
            const I widening = from_doubles(field.integer(0), -radius, radius);
            for (int k = 0; k < 3; ++k)
                for (int j = 0; j < 3; ++j) result.region[k][j] = result.center[k][j] + widening;
            for (const double rho : {0.0, 1.0, 10.0, 100.0, 1000.0, 10000.0})
                if (hessian_positive_definite(result, p, rho)) {
                    result.rho = rho;
                    result.radius = radius;
                    result.verdict = Outcome::proved;
                    result.reason = "the augmented Lagrangian's Hessian is positive definite on the whole region (rho = " +
                                    std::to_string(static_cast<long>(rho)) + ")";
                    return true;
                }
        }
        return false;
    });
    if (proved.status == ContractStatus::too_wide) result.reason = proved.reason();
    if (proved.status == ContractStatus::too_wide || *proved.value) return result;
    result.region = result.center;
    result.reason = "the Hessian was not proved positive definite on a region of radius down to " + std::to_string(radius * 4);
    return result;
}

template <class I>
bool region_contains(const ClosingRegion<I>& region, const Basis<I>& basis) {
    if (region.verdict != Outcome::proved) return false;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            if (!contains(region.region[k][j], basis[k][j])) return false;
    return true;
}

template ClosingRegion<DInterval> certify_closing_region(const LocalOptimum<DInterval>&, const DInterval&, double, int);
template bool region_contains(const ClosingRegion<DInterval>&, const Basis<DInterval>&);

}  // namespace superpack
