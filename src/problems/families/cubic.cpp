// The enclosure of C0 and C1 (JST 2009, Eqs. 1-3 and 8-10) at p, the family's entry in the registry
// (family_registry.hpp); its equations are in families.hpp.
#include "family_enclosure.hpp"

#include <algorithm>
#include <cmath>

#include "superpack/solve/guess.hpp"

namespace superpack {

// C0 and C1: certify the root s in a small box by interval Newton, then prove [0, box) free
// of roots, so that s is the smallest positive root as Eqs. 2 and 9 require.
template <class I>
FamilyLattice<I> enclose_cubic(Family family, const I& p) {
    FamilyLattice<I> lattice{family};
    const auto field = field_of(p);
    // The guess starts at 1 - t, where f = s^(2p) + 2^(-2p) > 0 (C0) or 2 s^(2p) > 0 (C1): f is
    // increasing and convex on s >= 0, so Newton descends monotonically to the root, in a few
    // steps for every p (from a fixed start such as 0.2 it needs about 2p steps at large p,
    // because (s + t)^(2p) only shrinks by a factor e per step there).
    const double p_guess = mid_double(p);
    const double start = cubic_constants(p_guess).deficit;
    const double s_guess = guess_root([&](const auto& s) { return cubic_equation(family, s, p_guess); }, start);
    const CubicConstants<I> constants = cubic_constants(p);
    auto equation = [&](const auto& s) { return cubic_equation(family, s, constants); };
    const double spread = width_upper(p);
    // Newton stops within 2^8 units in the last place of s: quadratic convergence jumps from
    // far above that to the rounding floor, so the stall test would only cost one more step.
    const double target_width = std::ldexp(s_guess, -static_cast<int>(field.bits()) + 8);
    // The first radius is relative to s, plus 4 |ds/dp| times the spread of p (an audit piece,
    // or the rounding of a p that is not a double), where |ds/dp| <= s/p is a guess that holds
    // on [1, 10] and asymptotically (s ~ ln2/(2p)).
    for (double radius = (1e-10 + 4 * spread / p_guess) * s_guess; radius < 0.5; radius *= 64) {
        // The lower end is cut to 24 significant bits so that a ball backend (30-bit radius)
        // holds [0, lower end] exactly: the root-free piece below must not reach the root.
        // It also sits at least 2^-20 s below the guess: a ball holding [0, lower end] + t
        // rounds its radius by 2^-30 of its width, which must not reach the root.
        int exponent = 0;
        const double mantissa = std::frexp(std::max(0.0, std::min(s_guess - radius, s_guess * (1 - 0x1p-20))), &exponent);
        const double lower_end = std::ldexp(std::floor(std::ldexp(mantissa, 24)), exponent - 24);
        const I box = from_doubles(field.integer(0), lower_end, s_guess + radius);
        NewtonResult<I> newton = newton_isolate(equation, box, target_width, 200);
        // The refined box must lie in the box the proof started from: every root there lies in
        // it, and [0, lower end) is shown root-free below, so the root is the smallest.
        if (newton.status != RootStatus::unique || !contains(newton.initial_box, newton.box)) continue;
        const I below = hull(field.integer(0), lower_point(newton.initial_box));
        auto vector_equation = [&](const auto& x) { return std::vector{equation(x[0])}; };
        lattice.search = isolate_roots(vector_equation, std::vector<I>{below}, 1e-6, 256, 0.0);
        const bool root_free = std::all_of(lattice.search.begin(), lattice.search.end(),
                                           [](const RootLeaf<I>& leaf) { return leaf.status == RootStatus::none; });
        lattice.search.push_back({{newton.initial_box}, RootStatus::unique, {newton.box}, newton.reason});
        lattice.branches.push_back({{{"s", newton.box}}, lattice.search.back()});
        if (!root_free) {
            lattice.message = "could not prove [0, s) free of roots";
            return lattice;
        }
        lattice.parameters = {{"s", newton.box}};
        finish(lattice, p, cubic_basis_with_shift(family, newton.box, constants.shift));
        return lattice;
    }
    lattice.message = "interval Newton did not isolate the root s";
    return lattice;
}

template FamilyLattice<DInterval> enclose_cubic(Family, const DInterval&);
template FamilyLattice<Ball> enclose_cubic(Family, const Ball&);

}  // namespace superpack
