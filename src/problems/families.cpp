#include "superpack/problems/families.hpp"

#include <algorithm>
#include <cmath>

#include "superpack/problems/local_optimality.hpp"
#include "superpack/problems/s6.hpp"
#include "superpack/solve/guess.hpp"

namespace superpack {

const char* to_string(Family family) {
    switch (family) {
        case Family::C0: return "C0";
        case Family::C1: return "C1";
        case Family::O0: return "O0";
        case Family::O1: return "O1";
        case Family::D14: return "D14";
        case Family::S6: return "S6";
        case Family::MinkowskiInsertion: return "minkowski-insertion";
    }
    return "?";
}

std::vector<Family> all_families() { return {Family::C0, Family::C1, Family::O0, Family::O1, Family::D14, Family::S6}; }

std::vector<Family> convex_families_and_insertion() {
    std::vector<Family> families = all_families();
    families.push_back(Family::MinkowskiInsertion);
    return families;
}

std::string family_source(Family family) {
    const std::string jst = "Jiao, Stillinger & Torquato, Phys. Rev. E 79, 041309 (2009), ";
    switch (family) {
        case Family::C0: return jst + "Eqs. 1-3";
        case Family::C1: return jst + "Eqs. 8-10";
        case Family::O0: return jst + "Eqs. 5-7";
        case Family::O1: return jst + "Eqs. 11-13";
        case Family::D14:
            return "Dostert & Vallentin, New dense superball packings in three dimensions, Adv. Geom. 20 (2020) 473-482, "
                   "Theorem 4.2";
        case Family::S6:
            return "superpack's own family (issue 12): the KKT point of min |det| for Minkowski's six pairs (configuration "
                   "A3), NOTES.md 4.2";
        case Family::MinkowskiInsertion:
            return jst + "Sec. IV.C, Eq. 10: the concave superball inside each octahedron of Minkowski's densest lattice "
                         "packing of octahedra";
    }
    return "";
}

Family parse_family(const std::string& name) {
    for (Family family : convex_families_and_insertion())
        if (name == to_string(family)) return family;
    throw InputError("unknown family '" + name + "' (expected C0, C1, O0, O1, D14, S6 or minkowski-insertion)");
}

Basis<Rational> minkowski_octahedron_basis() {
    return Basis<Rational>{{{Rational(2, 3), Rational(2, 3), Rational(-2, 3)},
                            {Rational(-1, 3), Rational(4, 3), Rational(-1, 3)},
                            {Rational(1, 3), Rational(-1, 3), Rational(-4, 3)}}};
}

std::string family_domain_text(Family family) {
    switch (family) {
        case Family::C0:
        case Family::C1: return "p >= 1";
        case Family::O0: return "1/2 < p <= 1";
        case Family::O1: return "p >= 1/2";
        case Family::D14: return "1/2 <= p <= 1";
        case Family::S6: return "ln3/ln4 < p < 1";
        case Family::MinkowskiInsertion: return "0 < p <= 1/2";
    }
    return "";
}

namespace {

// p*_o = ln 3 / ln 4, where the Minkowski branch of Eq. 12 reaches q = 0 (NOTES.md).
template <class I>
I octahedral_crossover(const I& like) {
    const auto field = field_of(like);
    return log(field.integer(3)) / log(field.integer(4));
}

// p > p*_o = ln3/ln4 for the exact p, decided on enclosures of ln3/ln4 at 64 to 4096 bits (p is
// rational and p*_o is not, so a fine enough enclosure separates them). A p that not even 4096
// bits separate from p*_o is refused with that reason.
bool above_octahedral_crossover(const Rational& p) {
    for (const long bits : {64L, 256L, 1024L, 4096L}) {
        const BallField field{bits};
        const Ball exact_p = field.rational(p), crossover = octahedral_crossover(exact_p);
        if (certainly_less(crossover, exact_p)) return true;
        if (certainly_less(exact_p, crossover)) return false;
    }
    throw InputError("p = " + decimal_or_fraction_text(p) +
                     " is too close to p*_o = ln3/ln4 to decide p > p*_o with 4096 bits: refused for S6");
}

}  // namespace

void require_in_domain(Family family, const Rational& p) {
    const Rational half(1, 2);
    // The floating-point guesses (of s for C0, C1, of the roots for O1) need 2p to be a finite
    // binary64 number with a normal reciprocal.
    static const Rational largest = [] {
        Rational power = 1;
        for (int k = 0; k < 300; ++k) power *= 10;
        return power;
    }();
    if (p > largest)
        throw InputError(std::string("p = ") + decimal_or_fraction_text(p) + " is beyond the supported p <= 10^300 of " +
                         to_string(family) + " (the floating-point guesses need 2p to be a finite binary64 number)");
    bool inside = true;
    switch (family) {
        case Family::C0:
        case Family::C1: inside = p >= 1; break;
        case Family::O0: inside = p > half && p <= 1; break;
        case Family::O1: inside = p >= half; break;
        case Family::D14: inside = p >= half && p <= 1; break;
        case Family::S6: inside = p < 1 && above_octahedral_crossover(p); break;
        case Family::MinkowskiInsertion: inside = p > 0 && p <= half; break;
    }
    if (!inside)
        throw InputError(std::string("p = ") + decimal_or_fraction_text(p) + " is outside the domain of " +
                         to_string(family) + " (" + family_domain_text(family) + ")");
}

namespace {

template <class I>
void finish(FamilyLattice<I>& lattice, const I& p, Basis<I> basis) {
    lattice.volume = enclose_ball_volume(p, 3);
    lattice.determinant = determinant(basis);
    lattice.phi = *lattice.volume / abs(*lattice.determinant);
    lattice.basis = std::move(basis);
    lattice.status = Outcome::proved;
}

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

template <class I>
FamilyLattice<I> enclose_o0(const I& p) {
    FamilyLattice<I> lattice{Family::O0};
    lattice.parameters = {{"c", octahedral_height(p)}};
    finish(lattice, p, o0_basis(p));
    return lattice;
}

// O1: every root of Eq. 12 with q >= 0 (roots come in pairs q, -q) in the box
// [0, 1] x [-1, 1], which holds all real roots since 2|q|^2p + |s|^2p = 1.
template <class I>
FamilyLattice<I> enclose_o1(const I& p) {
    FamilyLattice<I> lattice{Family::O1};
    const auto field = field_of(p);
    auto equations = [&](const auto& x) { return o1_equations(x, p); };
    const std::vector<I> box{hull(field.integer(0), field.integer(1)), hull(field.integer(-1), field.integer(1))};
    lattice.search = isolate_roots(equations, box, 1e-7, 20000, 0.0);
    std::size_t undecided = 0;
    for (const RootLeaf<I>& leaf : lattice.search) {
        if (leaf.status == RootStatus::unique) lattice.branches.push_back({{{"q", leaf.root[0]}, {"s", leaf.root[1]}}, leaf});
        if (leaf.status == RootStatus::undecided) ++undecided;
    }
    std::sort(lattice.branches.begin(), lattice.branches.end(), [](const RootBranch<I>& a, const RootBranch<I>& b) {
        return mid_double(a.unknowns[1].value) > mid_double(b.unknowns[1].value);
    });
    const I crossover = octahedral_crossover(p);
    const bool before = certainly_less(p, crossover), after = certainly_less(crossover, p);
    // Beyond p*_o there is no lattice on the branch whatever the search finds: the roots are
    // listed for information only, so undecided pieces (at large p, where the equations are
    // nearly flat in q) do not make the verdict undecided.
    if (after) {
        lattice.status = Outcome::refuted;
        lattice.message = "the Minkowski branch of Eq. (12) ends at p*_o = ln3/ln4; here Eq. (12) has " +
                          std::to_string(lattice.branches.size()) + " root(s) with q >= 0" +
                          (undecided > 0 ? " certified (" + std::to_string(undecided) + " pieces of the (q, s) box undecided)" : "") +
                          ", none on that branch";
        return lattice;
    }
    if (undecided > 0) {
        lattice.message = std::to_string(undecided) + " pieces of the (q, s) box undecided";
        return lattice;
    }
    if (!before || lattice.branches.size() != 2) {
        lattice.message = "expected two roots of Eq. (12) below p*_o, found " + std::to_string(lattice.branches.size());
        return lattice;
    }
    // Below p*_o the Minkowski branch is the root with the larger s (NOTES.md, "O1 branches").
    const I& q = lattice.branches[0].unknowns[0].value;
    const I& s = lattice.branches[0].unknowns[1].value;
    lattice.parameters = {{"l", o1_l(p)}, {"q", q}, {"s", s}};
    finish(lattice, p, o1_basis(q, s, p));
    return lattice;
}

// D14: every root of the system with x >= 0 in the box d14_search_box (it holds [0,1] x [-1,1]^2,
// and the first equation bounds |x|, |y|, |z| by 1), then the branch: the one root with x, y,
// z certainly > 0 and y certainly < z (NOTES.md 4.1). Roots with x < 0 cannot be on the branch,
// so the half box suffices; the mirror root (x, z, y) (the same lattice reflected) has y > z.
template <class I>
FamilyLattice<I> enclose_d14(const I& p) {
    FamilyLattice<I> lattice{Family::D14};
    const auto field = field_of(p);
    auto equations = [&](const auto& v) { return d14_equations(v, p); };
    lattice.search = isolate_roots(equations, d14_search_box(p), 1e-7, 40000, 0.0);
    std::size_t undecided = 0;
    std::vector<std::size_t> on_branch, possibly;
    for (const RootLeaf<I>& leaf : lattice.search) {
        if (leaf.status == RootStatus::undecided) ++undecided;
        if (leaf.status != RootStatus::unique) continue;
        const I& x = leaf.root[0];
        const I& y = leaf.root[1];
        const I& z = leaf.root[2];
        // Off the branch only when a condition certainly fails: a box of x, y or z that merely
        // touches 0 leaves the root undecided.
        const I zero = field.integer(0);
        const bool off = certainly_less(x, zero) || certainly_less(y, zero) || certainly_less(z, zero) || certainly_less(z, y);
        const bool on = certainly_positive(x) && certainly_positive(y) && certainly_positive(z) && certainly_less(y, z);
        lattice.branches.push_back({{{"x", x}, {"y", y}, {"z", z}}, leaf});
        if (on) on_branch.push_back(lattice.branches.size() - 1);
        else if (!off) possibly.push_back(lattice.branches.size() - 1);
    }
    const std::string count = std::to_string(lattice.branches.size()) + " root(s) with x >= 0 certified";
    if (!possibly.empty()) {
        lattice.message = count + ", " + std::to_string(possibly.size()) +
                          " of them not certainly on or off the branch x, y, z > 0, y < z (it ends at p*_o = ln3/ln4, "
                          "where it meets its mirror y = z)";
        return lattice;
    }
    if (on_branch.empty()) {
        if (undecided > 0) {
            lattice.message = count + ", none with x, y, z > 0 and y < z; " + std::to_string(undecided) +
                              " pieces of the (x, y, z) box undecided";
            return lattice;
        }
        lattice.status = Outcome::refuted;
        lattice.message = count + ", none with x, y, z > 0 and y < z: no lattice on the Dostert-Vallentin branch";
        return lattice;
    }
    if (undecided > 0 || on_branch.size() != 1) {
        lattice.message = undecided > 0 ? std::to_string(undecided) + " pieces of the (x, y, z) box undecided"
                                        : std::to_string(on_branch.size()) + " roots with x, y, z > 0 and y < z";
        return lattice;
    }
    // The branch root first, as for O1; the others follow in the order of the search.
    std::rotate(lattice.branches.begin(), lattice.branches.begin() + static_cast<long>(on_branch.front()),
                lattice.branches.begin() + static_cast<long>(on_branch.front()) + 1);
    // Krawczyk on a wide piece stops once one step no longer halves the box; run again from the
    // root box (it holds the root, and so does every iterate) until the box stops shrinking. The
    // checker tightens its own box the same way (checker/family_parameters.cpp).
    std::vector<I> root = lattice.branches.front().proof.root;
    for (int round = 0; round < 16; ++round) {
        const KrawczykResult<I> tighter = krawczyk_isolate(equations, root, 0.0, 60);
        if (tighter.status != RootStatus::unique) break;
        double before = 0, after = 0;
        for (std::size_t k = 0; k < root.size(); ++k) {
            before = std::max(before, width_upper(root[k]));
            after = std::max(after, width_upper(tighter.box[k]));
        }
        root = tighter.box;
        if (!(after < 0.5 * before)) break;
    }
    for (std::size_t k = 0; k < root.size(); ++k) lattice.branches.front().unknowns[k].value = root[k];
    lattice.parameters = lattice.branches.front().unknowns;
    finish(lattice, p, d14_basis(root[0], root[1], root[2]));
    return lattice;
}

// S6 (NOTES.md 4.2): the KKT point of min det B subject to ||c_i B||_(2p) = 2 for the six
// triples of s6_contact_triples, on the branch through the seed at p = 9/10. The
// floating-point continuation (s6_guess) only guesses it; Krawczyk on kkt_equations proves
// exactly one KKT point in a small box about the guess, and the basis is that root box. A step
// that fails leaves S6 undecided with the reason, never another lattice.
template <class I>
FamilyLattice<I> enclose_s6(const I& p) {
    FamilyLattice<I> lattice{Family::S6};
    const auto field = field_of(p);
    if (!certainly_less(octahedral_crossover(p), p)) {
        lattice.message = "p is not certainly above p*_o = ln3/ln4 at this precision, where S6 begins (try --digits 30)";
        return lattice;
    }
    if (!certainly_less(p, field.integer(1))) {
        lattice.message = "p is not certainly below 1, where S6 ends (at p = 1 rotations leave no isolated KKT point)";
        return lattice;
    }
    std::string failure;
    const std::optional<KktPoint> guess = s6_guess(mid_double(p), failure);
    if (!guess) {
        lattice.message = failure;
        return lattice;
    }
    const std::vector<Coefficients>& triples = s6_contact_triples();
    KrawczykResult<I> root;
    try {
        root = isolate_kkt_point(*guess, triples, p);
    } catch (const std::domain_error& error) {
        lattice.message = std::string("an enclosure was too wide for a power's contract (") + error.what() + ")";
        return lattice;
    }
    lattice.search.push_back({root.initial_box, root.status, root.box, root.reason});
    if (root.status != RootStatus::unique) {
        lattice.message = "Krawczyk did not prove a unique KKT point near the continued guess (" + root.reason + ")";
        return lattice;
    }
    std::vector<NamedValue<I>> unknowns;
    for (int k = 0; k < 9; ++k)
        unknowns.push_back({"b" + std::to_string(k / 3) + std::to_string(k % 3), root.box[static_cast<std::size_t>(k)]});
    for (std::size_t i = 0; i < triples.size(); ++i) unknowns.push_back({"mu" + std::to_string(i + 1), root.box[9 + i]});
    lattice.branches.push_back({unknowns, lattice.search.back()});
    lattice.parameters = unknowns;
    const std::vector<I>& x = root.box;
    finish(lattice, p, Basis<I>{{{x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}}});
    return lattice;
}

}  // namespace

template <class I>
FamilyLattice<I> enclose_family_at(Family family, const I& p) {
    switch (family) {
        case Family::C0:
        case Family::C1: return enclose_cubic(family, p);
        case Family::O0: return enclose_o0(p);
        case Family::O1: return enclose_o1(p);
        case Family::D14: return enclose_d14(p);
        case Family::S6: return enclose_s6(p);
        case Family::MinkowskiInsertion: {
            FamilyLattice<I> lattice{family};  // no parameters: the basis does not depend on p
            finish(lattice, p, enclose_basis(minkowski_octahedron_basis(), field_of(p)));
            return lattice;
        }
    }
    return FamilyLattice<I>{family};
}

FamilyLattice<DInterval> enclose_family(Family family, const Rational& p, const DoubleField& field) {
    require_in_domain(family, p);
    return enclose_family_at(family, field.rational(p));
}

FamilyLattice<Ball> enclose_family(Family family, const Rational& p, const BallField& field) {
    require_in_domain(family, p);
    return enclose_family_at(family, field.rational(p));
}

template FamilyLattice<DInterval> enclose_family_at(Family, const DInterval&);
template FamilyLattice<Ball> enclose_family_at(Family, const Ball&);

}  // namespace superpack
