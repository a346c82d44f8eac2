// Replaying the steps of a proof tree in the checker's arithmetic: interval Newton (1-D),
// Krawczyk (n-D), a one-signed component, and the covering of a box by a bisection tree.
// Shared by the claim kinds (claim_*.cpp); each check names its path when it fails.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "checker/verifier.hpp"

namespace superpack_checker {

using Box = std::vector<Real>;

// Every entry of `inner` inside the same entry of `outer` (boxes of one dimension).
bool box_inside(const Box& inner, const Box& outer);

// F: R^n -> R^n with an interval Jacobian enclosure (or slope enclosure) over a box.
struct System {
    std::function<std::vector<Real>(const Box&)> value;
    std::function<std::vector<std::vector<Real>>(const Box&)> jacobian;
};

enum class ReplayStatus { none, unique, undecided };

struct KrawczykReplay {
    ReplayStatus status = ReplayStatus::undecided;
    Box root;  // unique: a box (tightened as far as the precision allows) holding the only root
    std::string reason;
};

// For F(x, p) with p in an interval P: the mean-value form F(m, p) in F(m, p0) + F_p(m, P) (p - p0),
// preconditioned term by term, C F(m, p0) + (C F_p(m, P)) (P - p0). C F(m, P) itself is sound but
// wide by |C| |F_p| |P - p0|, which on an ill-conditioned system (S6's KKT point) is far wider
// than |C F_p| |P - p0|: the cancellation happens inside C F_p (NOTES.md 4.2).
struct ParameterForm {
    std::function<std::vector<Real>(const Box&)> value_at_p0;  // F(x, p0), p0 in P
    std::function<std::vector<Real>(const Box&)> derivative;   // dF/dp (x, P)
    Real offset;                                                // P - p0
};

// K(X) = m - C F(m) + (I - C J(X)) (X - m) with C a floating-point inverse of the midpoint
// Jacobian (any C is sound), iterating X <- K(X) ∩ X: every root in the box stays in X.
// K(X) ∩ X empty proves no root; K(X) in int X proves exactly one (then iterated until it
// stops shrinking, to give a tight root box).
// With `parameter`, C F(m) is its mean-value form: then a unique root for every p of P.
KrawczykReplay replay_krawczyk(const System& system, const Box& box, int max_iterations,
                               const ParameterForm* parameter = nullptr);

// Interval Newton for f: R -> R from a stored box X and point M in X: checks 0 not in f'(X)
// and N(X) = M - f(M)/f'(X) in int X, or in the interior of a later iterate X_k = N(X_(k-1)) ∩
// X_(k-1) (rejecting at `path` otherwise, and comparing with the stored derivative and first
// image when given), then iterates to a tight box around the root.
Real replay_newton(Context& context, const std::function<Real(const Real&)>& f,
                   const std::function<Real(const Real&)>& derivative, const Real& box, const Real& center,
                   const Real* stored_derivative, const Real* stored_image, const std::string& path);

// Walks a tree of {"kind": "split", "box", "dimension", "cases": [a, b]} nodes, checking that
// the children of each node cover its box, and hands every other node to `leaf`. Returns the
// box of the root node (the caller checks it covers the region the claim needs).
using LeafCheck = std::function<void(const Json& leaf, const Box& box, const std::string& path)>;
Box check_partition(Context& context, const Json& node, const std::string& path, const LeafCheck& leaf);

// Leaf checks against a system: "excluded" (a component of F has one sign on the box, the
// stored values containing the checker's), "krawczyk" with status none or unique (the root
// box stored must hold the checker's own). For unique leaves the checker's root box is
// appended to `roots`.
void check_root_leaf(Context& context, const System& system, const Json& leaf, const Box& box,
                     const std::string& path, std::vector<Box>* roots);

// Does the stated enclosure (at `path`) contain the checker's own enclosure `own` of the same
// value, and is it no wider than `own` allows (enclosure_width_factor, enclosure_slack_bits in
// limits.hpp)? Every caller passes an enclosure the checker computed itself, never one it read.
void check_encloses(Context& context, const Json& stated, const std::string& path, const Real& own);

bool disjoint(const Box& a, const Box& b);

}  // namespace superpack_checker
