// Superdisks |x|^(2p) + |y|^(2p) <= 1: the Lambda0 and Lambda1 lattices of Jiao, Stillinger &
// Torquato (PRL 100, 245504, 2008) and a certified optimum over all lattice packings
// (which, by Fejes Toth, is the optimum over all packings when p >= 1/2). NOTES.md section 7.
//
// Scale: K is the unit superdisk; translates K + w, w in a lattice L, pack iff L has no
// nonzero point in the interior of 2K. We work with points u, v on the boundary of K and
// report the packing lattice 2L (basis 2u, 2v, determinant 4 det(u, v)).
//
// Parameter: u(t) = (1, t) / ||(1, t)||_q, q = 2p, t in [0, 1] (from the x-axis, t = 0, to
// the diagonal, t = 1). v(t) is the point of bd K with v - u in bd K and det(u, v) > 0;
// D(t) = det(u(t), v(t)). Lambda1 is t = 0, Lambda0 is t = 1.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <string>
#include <vector>

#include "superpack/solve/newton.hpp"
#include "superpack/solve/root_partition.hpp"
#include "superpack/geometry/superball.hpp"

namespace superpack {

// ---- formulas (templates over the scalar T of t and the unknowns, Q of q = 2p) -----------

// x(t) = (1 + t^q)^(-1/q): the first coordinate of u(t); u(t) = (x, t x).
template <class T, class Q>
T boundary_x(const T& t, const Q& q) {
    const T one = constant_like(t, 1);
    return pow_nonneg(one + pow_abs(t, q), -(constant_like(q, 1) / q));
}

// The contact equations of v = (a, b): v on bd K and v - u(t) on bd K.
template <class T, class Q>
std::array<T, 2> contact_equations(const T& a, const T& b, const T& t, const Q& q) {
    const T one = constant_like(t, 1);
    const T x = boundary_x(t, q);
    const T y = t * x;
    return {pow_abs(a, q) + pow_abs(b, q) - one, pow_abs(a - x, q) + pow_abs(b - y, q) - one};
}

// det(u(t), v) for v = (a, b).
template <class T, class Q>
T hexagon_determinant(const T& a, const T& b, const T& t, const Q& q) {
    const T x = boundary_x(t, q);
    return x * b - t * x * a;
}

// y1 = (1 - 2^-q)^(1/q), as exp(log1p(-2^-q) / q): at t = 0 the contact system reads
// |a|^q + |b|^q = 1 = |a - 1|^q + |b|^q, so |a| = |a - 1|, a = 1/2, and b = y1 > 0 (det > 0).
// This is v(0) (Lambda1) in closed form; Krawczyk cannot prove it for large q, where the
// system's dependence on a is of size 2^-q (NOTES.md 7.3).
template <class Q>
Q axis_height(const Q& q) {
    const auto field = field_of(q);
    return exp(log1p(-exp(-q * log(field.integer(2)))) / q);
}

// A lower bound of D(t) = det(u(t), v) over a piece T of [0, 1] (q > 1) for every solution v =
// (a, b) of the contact system with det(u, v) > 0, with no enclosure of v (NOTES.md 7.4, "A
// priori bound"): b >= y1, and a <= 0 or 0 <= a <= min(x/2, x - (1 - 2^-q - (y1 - t x)^q)^(1/q)),
// so D = x b - t x a >= x y1 - t x max(0, that). It is what the branch and bound uses where
// Krawczyk cannot follow v(t): for large q, v leaves the axis within t ~ 2^-q and the contact
// system has condition ~1/(q t) beyond, while D there is far above its minimum.
template <class Q>
Q a_priori_lower_bound(const Q& t, const Q& q) {
    const auto field = field_of(q);
    const Q zero = field.integer(0), one = field.integer(1), two = field.integer(2);
    const Q x = boundary_x(t, q), height = axis_height(q);
    const Q gap = one - exp(-q * log(two)) - pow_abs(height - t * x, q);
    const Q root = certainly_positive(gap) ? pow_nonneg(lower_point(gap), one / q) : zero;
    // Both are upper bounds of a >= 0; which one is used is a choice, not a claim.
    const Q half = x / two, complement = x - root;
    const Q a = mid_double(upper_point(half)) < mid_double(upper_point(complement)) ? half : complement;
    return lower_point(x * height - t * x * hull(zero, upper_point(a)));
}

template <class I> I lift_like(const I& x, const I&) { return x; }
template <class I> Jet<I> lift_like(const I& x, const Jet<I>&) { return constant(x); }

// The contact system for Krawczyk, at a fixed t that may be an interval: a proof over a box
// then holds for every t in it (the Jacobian and f(m) are enclosed over all such t).
template <class I>
struct ContactSystem {
    I t, q;
    template <class S>
    std::vector<S> operator()(const std::vector<S>& v) const {
        const auto equations = contact_equations(v[0], v[1], lift_like(t, v[0]), q);
        return {equations[0], equations[1]};
    }
};

// ---- results -------------------------------------------------------------------------------

enum class PieceVerdict { discarded, monotone, bounded, undecided };
const char* to_string(PieceVerdict verdict);

// How a piece's lower bound of D was obtained (a certificate replays exactly that method).
// `a_priori`: a piece without a Krawczyk proof, bounded by a_priori_lower_bound.
enum class LowerBoundMethod { naive, naive_and_mean_value, left_end, right_end, a_priori };
const char* to_string(LowerBoundMethod method);

// One piece of the parameter range [0, 1] and what is proved about D on it.
template <class I>
struct HexagonPiece {
    I t;                    // the piece
    PieceVerdict verdict;
    I lower_bound;          // its lower end is a lower bound of D on the piece
    std::vector<I> v;       // Krawczyk enclosure of v(t) for all t in the piece
    I derivative;           // enclosure of D'(t) on the piece (when computed)
    std::string reason;
    std::vector<I> search_box;  // the box on which K(X) in int X was proved (for certificates)
    LowerBoundMethod method = LowerBoundMethod::naive;
    I center;               // naive_and_mean_value: the point m of D(m) + D'(T)(T - m)
};

// The lattice with u(t), v(t), v - u on bd K, as a packing lattice of K (basis 2u, 2v).
template <class I>
struct HexagonLattice {
    explicit HexagonLattice(const I& zero)
        : t(zero), basis{{{zero, zero}, {zero, zero}}}, determinant(zero), phi(zero) {}
    RootStatus status = RootStatus::undecided;
    I t;
    std::array<std::array<I, 2>, 2> basis;  // rows 2u, 2v
    I determinant;                          // 4 det(u, v) > 0
    I phi;
    std::string reason;
    std::vector<I> search_box;  // the box on which K(X) in int X proved v(t) (for certificates)
};

enum class OptimumStatus { certified, undecided, not_applicable };
const char* to_string(OptimumStatus status);

template <class I>
struct SuperdiskReport {
    explicit SuperdiskReport(const I& zero)
        : area(zero), lambda0(zero), lambda1(zero), optimal_determinant(zero), optimal_phi(zero),
          optimal_lattice(zero), gap_lambda0(zero), gap_lambda1(zero) {}
    I area;
    HexagonLattice<I> lambda0, lambda1;
    OptimumStatus status = OptimumStatus::not_applicable;
    std::string message;
    I optimal_determinant;  // min over lattices of 4 det(u, v): Delta(2K)
    I optimal_phi;
    std::vector<I> argmin_t;  // disjoint t-intervals covering every possible minimiser
    HexagonLattice<I> optimal_lattice;  // the best lattice found (upper bound witness)
    std::string attained_by;            // Lambda0, Lambda1, "Lambda0 and Lambda1", other, undecided
    I gap_lambda0, gap_lambda1;         // optimal_phi - phi(family), >= 0 in truth
    std::vector<HexagonPiece<I>> pieces;
    bool tiling = false;  // p = 1/2: the square tiles, optimum 1 without branch and bound
};

struct SuperdiskOptions {
    double relative_tolerance = 4e-10;  // stopping rule of the branch and bound (a guess)
    std::size_t max_pieces = 1000;
};

// The supported range is p <= 10^6 (throws InputError beyond, NOTES.md 7.4 "Large p"): near its
// minimum D differs from 1 by about (ln 2)^2 / (2p)^2, 1e-13 at p = 10^6; beyond, binary64 cannot
// resolve it (undecided at p = 10^7) and Arb's branch and bound took over five minutes at 10^8.
extern const Rational superdisk_largest_p;

SuperdiskReport<DInterval> analyse_superdisk(const Rational& p, const DoubleField& field,
                                             const SuperdiskOptions& options = {});
SuperdiskReport<Ball> analyse_superdisk(const Rational& p, const BallField& field, const SuperdiskOptions& options = {});

// The lattice at one parameter t (a point), certified by Krawczyk.
HexagonLattice<DInterval> enclose_hexagon_lattice(const Rational& t, const Rational& p, const DoubleField& field);
HexagonLattice<Ball> enclose_hexagon_lattice(const Rational& t, const Rational& p, const BallField& field);

}  // namespace superpack
