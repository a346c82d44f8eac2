// Certified root isolation: a 1-D interval Newton operator and an n-D Krawczyk operator,
// and a branch-and-bound that accounts for every piece of a search box.
//
// Existence and uniqueness are separate facts (CAPD, IBEX): `existence` is set when the
// operator maps the box into its own interior (Brouwer / Krawczyk), `uniqueness` when the
// derivative (or the preconditioned Jacobian) is proved nonsingular on the box. A box is
// reported RootStatus::unique only when both hold. RootStatus::none means the box is proved
// to hold no root. Everything else is RootStatus::undecided, with a reason.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "superpack/jet.hpp"

namespace superpack {

enum class [[nodiscard]] RootStatus { unique, none, undecided };

inline const char* to_string(RootStatus status) {
    switch (status) {
        case RootStatus::unique: return "unique";
        case RootStatus::none: return "none";
        case RootStatus::undecided: return "undecided";
    }
    return "undecided";
}

template <class I>
struct NewtonResult {
    RootStatus status = RootStatus::undecided;
    I box;                 // the root (if any) lies in box; for `unique`, exactly one does
    I initial_box;         // the box the proof is about
    I derivative;          // enclosure of f' over initial_box (excludes 0 for `unique`)
    bool existence = false;
    bool uniqueness = false;
    int iterations = 0;
    std::string reason;
};

// Interval Newton on f: R -> R over `box`, N(X) = m - f(m) / f'(X).
// `f` is a generic callable evaluated at I (values) and at Jet<I> (value and derivative).
// Iterates X <- N(X) ∩ X until the box is narrower than `target_width` or stops shrinking.
template <class I, class F>
NewtonResult<I> newton_isolate(const F& f, const I& box, double target_width, int max_iterations) {
    NewtonResult<I> result{RootStatus::undecided, box, box, box, false, false, 0, ""};
    I current = box;
    for (int iteration = 1; iteration <= max_iterations; ++iteration) {
        result.iterations = iteration;
        const Jet<I> jet = f(variable(current));
        if (iteration == 1) result.derivative = jet.derivative;
        // An unbounded derivative (a power below 1 at 0) bounds no step: undecided.
        const bool unbounded = !bounded(jet.derivative);
        if (unbounded || contains_zero(jet.derivative)) {
            if (!contains_zero(jet.value)) {
                result.status = RootStatus::none;
                result.reason = "f has one sign on the box";
            } else if (!result.existence) {
                result.reason = unbounded ? "derivative unbounded on the box" : "derivative may vanish on the box";
            }
            return result;
        }
        if (iteration == 1) result.uniqueness = true;  // f monotone on the initial box
        const I center = midpoint(current);
        const I step = value_of(f(center)) / jet.derivative;
        const I image = center - step;
        I next = image;
        if (!intersect(next, image, current)) {
            result.status = RootStatus::none;
            result.reason = "Newton image disjoint from the box";
            return result;
        }
        if (!result.existence && interior_contains(current, image)) {
            result.existence = true;
            result.status = RootStatus::unique;
            result.reason = "N(X) in interior of X and f' != 0 on X";
        }
        const double before = width_upper(current), after = width_upper(next);
        current = next;
        result.box = current;
        if (result.existence && (after <= target_width || after >= 0.5 * before)) break;
    }
    if (!result.existence) result.reason = "Newton operator did not contract into the box";
    return result;
}

template <class I>
struct KrawczykResult {
    RootStatus status = RootStatus::undecided;
    std::vector<I> box;          // the root (if any) lies in box
    std::vector<I> initial_box;  // the box the proof is about
    bool existence = false;
    bool uniqueness = false;
    int iterations = 0;
    std::string reason;
};

// Krawczyk operator K(X) = m - C f(m) + (Id - C J(X)) (X - m), with C a floating-point
// inverse of the midpoint Jacobian (any C is sound; a good one makes K contract).
// K(X) ⊂ int X proves a unique zero in X; K(X) ∩ X = ∅ proves none. `f` maps a
// std::vector of I or of Jet<I> to a vector of the same length.
//
// The interval part is written with plain loops over std::vector rather than Eigen
// matrices of intervals: Eigen needs Scalar(0) conversions and a default-constructed
// scalar, and a Ball has no meaningful precision until it is made from a field.
template <class I, class F>
KrawczykResult<I> krawczyk_isolate(const F& f, const std::vector<I>& box, double target_width,
                                   int max_iterations) {
    const std::size_t n = box.size();
    const auto field = field_of(box[0]);
    KrawczykResult<I> result{RootStatus::undecided, box, box, false, false, 0, ""};
    std::vector<I> current = box;
    for (int iteration = 1; iteration <= max_iterations; ++iteration) {
        result.iterations = iteration;
        const std::vector<I> values = f(current);
        for (std::size_t i = 0; i < n; ++i)
            if (!contains_zero(values[i])) {
                result.status = result.existence ? result.status : RootStatus::none;
                if (!result.existence) result.reason = "a component of f has one sign on the box";
                return result;
            }
        // Jacobian over the box, one column per seeded variable.
        std::vector<std::vector<I>> jacobian(n, std::vector<I>(n, field.integer(0)));
        for (std::size_t j = 0; j < n; ++j) {
            std::vector<Jet<I>> seeded;
            for (std::size_t k = 0; k < n; ++k) seeded.push_back(k == j ? variable(current[k]) : constant(current[k]));
            const std::vector<Jet<I>> column = f(seeded);
            for (std::size_t i = 0; i < n; ++i) jacobian[i][j] = column[i].derivative;
        }
        // An unbounded entry (a power below 1 at 0) bounds no contraction: undecided.
        for (const std::vector<I>& row : jacobian)
            for (const I& entry : row)
                if (!bounded(entry)) {
                    if (!result.existence) result.reason = "Jacobian unbounded on the box";
                    return result;
                }
        Eigen::MatrixXd middle(n, n);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) middle(i, j) = mid_double(jacobian[i][j]);
        Eigen::FullPivLU<Eigen::MatrixXd> lu(middle);
        if (!lu.isInvertible()) {
            result.reason = "midpoint Jacobian singular";
            return result;
        }
        const Eigen::MatrixXd inverse = lu.inverse();
        std::vector<I> center, offset;
        for (std::size_t k = 0; k < n; ++k) {
            center.push_back(midpoint(current[k]));
            offset.push_back(current[k] - center[k]);
        }
        const std::vector<I> at_center = f(center);
        std::vector<I> image;
        bool interior = true, disjoint = false;
        for (std::size_t i = 0; i < n; ++i) {
            I k = center[i];
            for (std::size_t j = 0; j < n; ++j) {
                const I c = from_doubles(field.integer(0), inverse(i, j), inverse(i, j));
                k = k - c * at_center[j];
                // Row i of (Id - C J(X)).
                I entry = field.integer(i == j ? 1 : 0);
                for (std::size_t l = 0; l < n; ++l)
                    entry = entry - from_doubles(field.integer(0), inverse(i, l), inverse(i, l)) * jacobian[l][j];
                k = k + entry * offset[j];
            }
            image.push_back(k);
            interior = interior && interior_contains(current[i], k);
            I meet = k;
            if (!intersect(meet, k, current[i])) disjoint = true;
        }
        if (disjoint) {
            if (!result.existence) {
                result.status = RootStatus::none;
                result.reason = "K(X) disjoint from X";
            }
            return result;
        }
        if (interior && !result.existence) {
            result.existence = result.uniqueness = true;
            result.status = RootStatus::unique;
            result.reason = "K(X) in interior of X";
        }
        double before = 0, after = 0;
        for (std::size_t i = 0; i < n; ++i) {
            before = std::max(before, width_upper(current[i]));
            I meet = image[i];
            intersect(meet, image[i], current[i]);
            current[i] = meet;
            after = std::max(after, width_upper(current[i]));
        }
        result.box = current;
        if (result.existence && (after <= target_width || after >= 0.5 * before)) break;
    }
    if (!result.existence) result.reason = "Krawczyk operator did not contract into the box";
    return result;
}

}  // namespace superpack

namespace superpack {

// One piece of a subdivided search box and what is proved about it.
template <class I>
struct RootLeaf {
    std::vector<I> piece;  // a piece of the partition of the search box
    RootStatus status;
    std::vector<I> root;   // for `unique`: the refined box holding the root
    std::string reason;
};

// Branch and bound over `box`: the returned pieces partition it, and every piece is
// `none` (a component of f excludes 0 there, or Krawczyk proved no zero), `unique`
// (Krawczyk proved exactly one zero in its interior) or `undecided` (narrower than
// `min_width`, or the budget of `max_pieces` ran out: such pieces are kept, never dropped).
template <class I, class F>
std::vector<RootLeaf<I>> isolate_roots(const F& f, const std::vector<I>& box, double min_width,
                                       std::size_t max_pieces, double target_width) {
    std::vector<RootLeaf<I>> leaves;
    std::vector<std::vector<I>> pending{box};
    while (!pending.empty()) {
        std::vector<I> piece = pending.back();
        pending.pop_back();
        bool excluded = false;
        for (const I& value : f(piece)) excluded = excluded || !contains_zero(value);
        if (excluded) {
            leaves.push_back({piece, RootStatus::none, {}, "a component of f has one sign"});
            continue;
        }
        const KrawczykResult<I> proof = krawczyk_isolate(f, piece, target_width, 60);
        if (proof.status == RootStatus::none) {
            leaves.push_back({piece, RootStatus::none, {}, proof.reason});
            continue;
        }
        if (proof.status == RootStatus::unique) {
            // Every root in the piece lies in proof.box, which holds exactly one root. A ball
            // backend rounds intersections outward, so proof.box may poke out of the piece:
            // the piece then holds that root only if proof.box lies inside it.
            bool inside = true, apart = false;
            for (std::size_t k = 0; k < piece.size(); ++k) {
                I meet = piece[k];
                inside = inside && contains(piece[k], proof.box[k]);
                apart = apart || !intersect(meet, piece[k], proof.box[k]);
            }
            if (inside) {
                leaves.push_back({piece, RootStatus::unique, proof.box, proof.reason});
                continue;
            }
            if (apart) {
                leaves.push_back({piece, RootStatus::none, {}, "the only root near the piece lies outside it"});
                continue;
            }
        }
        std::size_t widest = 0;
        for (std::size_t k = 1; k < piece.size(); ++k)
            if (width_upper(piece[k]) > width_upper(piece[widest])) widest = k;
        if (width_upper(piece[widest]) < min_width || leaves.size() + pending.size() + 2 > max_pieces) {
            leaves.push_back({piece, RootStatus::undecided, {}, proof.reason + "; subdivision budget reached"});
            continue;
        }
        const I center = midpoint(piece[widest]);
        std::vector<I> left = piece, right = piece;
        left[widest] = hull(lower_point(piece[widest]), center);
        right[widest] = hull(center, upper_point(piece[widest]));
        pending.push_back(right);
        pending.push_back(left);
    }
    return leaves;
}

}  // namespace superpack
