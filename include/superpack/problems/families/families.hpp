// The four lattice families of Jiao, Stillinger & Torquato (2009), the 14-neighbour family
// D14 of Dostert & Vallentin (2020), superpack's six-pair family S6 (problems/families/s6_definition.hpp) and the
// paper's Minkowski insertion for concave superballs: their contact equations, certified
// parameters, bases and densities phi = V_sb(p) / |det basis|.
//
// Every equation is a template over the scalar of its unknowns (S) and of p (P), each an
// interval or a Jet, so Newton/Krawczyk (d/d unknowns) and the crossover and slope
// drivers (d/dp) use one source per formula.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "superpack/arith/outcome.hpp"
#include "superpack/geometry/lattice_basis.hpp"
#include "superpack/solve/newton.hpp"
#include "superpack/solve/root_partition.hpp"
#include "superpack/geometry/superball.hpp"

namespace superpack {

enum class Family { C0, C1, O0, O1, D14, S6, MinkowskiInsertion };

const char* to_string(Family family);
Family parse_family(const std::string& name);  // throws InputError
// The convex families (p >= 1/2), which the report, `best` and `audit` run through; the insertion
// (0 < p <= 1/2) only by its name.
std::vector<Family> all_families();
// The convex families and then the insertion: what `best` checks at p, each where its domain holds.
std::vector<Family> convex_families_and_insertion();

// The insertion (JST 2009, Sec. IV.C, Eq. 10): for 0 < p <= 1/2 the superball lies in the
// octahedron |x| + |y| + |z| <= 1 (sum |x_i|^(2p) <= 1 makes each |x_i| <= 1, so |x_i| <= |x_i|^(2p)),
// so the lattice of Minkowski's densest octahedron packing, exact and the same for every p, packs
// it: rows (2/3, 2/3, -2/3), (-1/3, 4/3, -1/3), (1/3, -1/3, -4/3), |det| = 38/27.
Basis<Rational> minkowski_octahedron_basis();
// Where the family is defined, for the tables and JSON: the paper and its equations.
std::string family_source(Family family);
// Claimed domain in words and as a predicate on exact p (throws InputError outside it).
std::string family_domain_text(Family family);
void require_in_domain(Family family, const Rational& p);

// x^y with y (and possibly x) varying: the mixed-scalar cases needed by d/dp.
template <class I> Jet<I> pow_nonneg(const I& x, const Jet<I>& y) { return exp(y * log(x)); }

// 2^(-1/(2p)) = exp(-log 2 / (2p)), the shift t of the C0 and C1 equations.
template <class P, class L>
P cubic_shift(const P& two_p, const L& log_two) {
    return exp(-log_two / two_p);
}

template <class P>
P cubic_shift(const P& p) {
    const auto field = scalar_field(p);
    return cubic_shift(field.integer(2) * p, log(field.integer(2)));
}

// The quantities of the C0/C1 equations that depend on p only, computed once per p so that
// Newton's many evaluations in s do not repeat them.
template <class P>
struct CubicConstants {
    P two_p;    // 2p
    P shift;    // t = 2^(-1/(2p))
    P deficit;  // 1 - t = -expm1(-ln2/(2p)), to full relative precision also at large p
    P corner;   // 2^(-2p)
};

template <class P>
CubicConstants<P> cubic_constants(const P& p) {
    const auto field = scalar_field(p);
    const P two_p = field.integer(2) * p;
    const auto log_two = log(field.integer(2));
    // t is taken from the deficit rather than from its own exp: 1 - (1 - t) loses nothing that
    // matters (t is near 1), and it saves one exponential per density.
    const P deficit = -expm1(-log_two / two_p);
    return {two_p, field.integer(1) - deficit, deficit, exp(-two_p * log_two)};
}

// C0 (Eq. 2): (s + t)^(2p) + s^(2p) + 2^(-2p) - 1 = 0, s the smallest positive root.
// C1 (Eq. 9): (s + t)^(2p) + 2 s^(2p) - 1 = 0.
// (s + t)^(2p) is evaluated as pow1p(s - (1 - t), 2p) = exp(2p log1p(s - (1 - t))), the same number for s > -t. For
// large p, s + t -> 1 while s ~ ln2/(2p): s + t rounded to the working precision would keep s
// only to 2p units in its last place, while s - (1 - t) has an absolute error of a few units of
// s, which 2p log1p turns into a few units of 1 (NOTES.md section 4, "Large p"). s and p each
// appear once inside log1p, as in s + t, so wide boxes of an audit piece stay tight.
template <class S, class P>
auto cubic_equation(Family family, const S& s, const CubicConstants<P>& c) {
    const auto field = scalar_field(c.two_p);
    const auto shifted = pow1p(s - c.deficit, c.two_p);
    // |s| rather than s: identical for s >= 0, and a box [0, b] made by a ball backend may
    // reach a rounding error below 0 (then the root-free claim covers a slightly larger set).
    const auto own = pow_abs(s, c.two_p);
    if (family == Family::C0) return shifted + own + c.corner - field.integer(1);
    return shifted + field.integer(2) * own - field.integer(1);
}

template <class S, class P>
auto cubic_equation(Family family, const S& s, const P& p) {
    return cubic_equation(family, s, cubic_constants(p));
}

// Bases (rows e1, e2, e3) of Eqs. 1, 8, 5, 11.
// With the shift t = 2^(-1/(2p)) already known (cubic_constants), or computed from p.
template <class T>
Basis<T> cubic_basis_with_shift(Family family, const T& s, const T& t) {
    const T side = constant_like(t, 2) * t;  // 2^(1 - 1/(2p))
    const T zero = constant_like(t, 0), one = constant_like(t, 1), two = constant_like(t, 2);
    if (family == Family::C0)
        return Basis<T>{{{side, side, zero}, {zero, zero, two}, {-(two * s), two * (s + t), one}}};
    return Basis<T>{{{side, side, zero}, {side, zero, side}, {two * (s + t), -(two * s), -(two * s)}}};
}

template <class T>
Basis<T> cubic_basis(Family family, const T& s, const T& p) {
    return cubic_basis_with_shift(family, s, cubic_shift(p));
}

// O0 (Eq. 5): the height c = (1 - 2^(1-2p))^(1/(2p)) of e3 = i + j + 2c k.
template <class P>
P octahedral_height(const P& p) {
    const auto field = scalar_field(p);
    const auto one = field.integer(1);
    const P base = one - exp((one - field.integer(2) * p) * log(field.integer(2)));
    return pow_nonneg(base, one / (field.integer(2) * p));
}

template <class T>
Basis<T> o0_basis(const T& p) {
    const T zero = constant_like(p, 0), one = constant_like(p, 1), two = constant_like(p, 2);
    return Basis<T>{{{two, zero, zero}, {zero, two, zero}, {one, one, two * octahedral_height(p)}}};
}

// O1 (Eq. 12) in the unknowns x = (q, s), with l = 3^(-1/(2p)):
//   2|q|^(2p) + |s|^(2p) - 1 = 0,   |l+q|^(2p) + |s-l|^(2p) + |l-q|^(2p) - 1 = 0.
template <class P>
P o1_l(const P& p) {
    const auto field = scalar_field(p);
    return exp(-log(field.integer(3)) / (field.integer(2) * p));
}

template <class S, class P>
std::vector<S> o1_equations(const std::vector<S>& x, const P& p) {
    const auto field = scalar_field(p);
    const auto two_p = field.integer(2) * p;
    const auto one = field.integer(1);
    const auto l = o1_l(p);
    const S& q = x[0];
    const S& s = x[1];
    return {field.integer(2) * pow_abs(q, two_p) + pow_abs(s, two_p) - one,
            pow_abs(q + l, two_p) + pow_abs(s - l, two_p) + pow_abs(l - q, two_p) - one};
}

template <class T>
Basis<T> o1_basis(const T& q, const T& s, const T& p) {
    const auto field = scalar_field(p);
    const T two_l = field.integer(2) * o1_l(p);
    const T two = constant_like(p, 2);
    return Basis<T>{{{two_l, two_l, -two_l}, {-(two * q), two * s, -(two * q)}, {two * q, -(two * q), -(two * s)}}};
}

// D14 (M. Dostert and F. Vallentin, New dense superball packings in three dimensions, Adv.
// Geom. 20 (2020) 473-482, Theorem 4.2; their exponent is our 2p) in the unknowns (x, y, z):
//   |x|^(2p) + |y|^(2p) + |z|^(2p) - 1 = 0,
//   |x-y|^(2p) + |z-x|^(2p) + |y+z|^(2p) - 1 = 0,
//   3 |-x+y+z|^(2p) - 1 = 0,
// the unit equations of b1 = (-x, y, z) (and its cyclic images b2, b3), of b1 + b2 = (z-x, y-x,
// y+z) (and b2 + b3, b3 + b1, the same terms permuted) and of b1 + b2 + b3 = (s, s, s), s = -x+y+z.
template <class S, class P>
std::vector<S> d14_equations(const std::vector<S>& v, const P& p) {
    const auto field = scalar_field(p);
    const auto two_p = field.integer(2) * p;
    const auto one = field.integer(1);
    const S& x = v[0];
    const S& y = v[1];
    const S& z = v[2];
    return {pow_abs(x, two_p) + pow_abs(y, two_p) + pow_abs(z, two_p) - one,
            pow_abs(x - y, two_p) + pow_abs(z - x, two_p) + pow_abs(y + z, two_p) - one,
            field.integer(3) * pow_abs(y + z - x, two_p) - one};
}

// The search box of D14: [0, 9/8] x [-9/8, 9/8]^2 holds every root with x >= 0 (the first
// equation bounds |x|, |y|, |z| by 1). Its ends are not +-1 so that no bisection point is
// dyadic like the coordinates 1/2 of the roots at p = 1/2: a root on a piece's face is in the
// interior of no piece, and Krawczyk could prove it in none.
template <class I>
std::vector<I> d14_search_box(const I& like) {
    const auto field = field_of(like);
    const I far = field.rational(Rational(9, 8));
    return {hull(field.integer(0), far), hull(-far, far), hull(-far, far)};
}

// Rows 2 b1, 2 b2, 2 b3 (contacts of norm 2, the convention of the other families).
template <class T>
Basis<T> d14_basis(const T& x, const T& y, const T& z) {
    const T two = constant_like(x, 2);
    const T a = two * x, b = two * y, c = two * z;
    return Basis<T>{{{-a, b, c}, {c, -a, b}, {b, c, -a}}};
}

// The certified description of one family at one p. Its status: proved (the lattice exists,
// printed "certified"), refuted (certified not to exist, "no_lattice") or undecided.

template <class I>
struct NamedValue {
    std::string name;
    I value;
};

template <class I>
struct RootBranch {
    std::vector<NamedValue<I>> unknowns;  // e.g. (q, s)
    RootLeaf<I> proof;
};

template <class I>
struct FamilyLattice {
    explicit FamilyLattice(Family which) : family(which) {}
    Family family;
    Outcome status = Outcome::undecided;
    std::string message;                    // why, when not certified
    std::vector<NamedValue<I>> parameters;  // s; or l, q, s; or c; or x, y, z; or b00..b22, mu1..mu6
    std::vector<RootBranch<I>> branches;    // every certified root of the contact equations
    std::vector<RootLeaf<I>> search;        // the partition behind "every root" (O1, D14), or the
                                            // root-free [0, s) and the Newton box (C0, C1), or the
                                            // Krawczyk leaf of the KKT point (S6)
    std::optional<Basis<I>> basis;
    std::optional<I> volume, determinant, phi;
};

// Certifies the family at p (an interval: a point for one p, a piece for the audit).
// Throws InputError when p is outside the family's claimed domain.
FamilyLattice<DInterval> enclose_family(Family family, const Rational& p, const DoubleField& field);
FamilyLattice<Ball> enclose_family(Family family, const Rational& p, const BallField& field);

template <class I>
FamilyLattice<I> enclose_family_at(Family family, const I& p);

}  // namespace superpack
