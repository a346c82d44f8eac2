// Certified root isolation in one dimension: the interval Newton operator.
#pragma once
#include <string>

#include "superpack/arith/jet.hpp"
#include "superpack/solve/root_status.hpp"

namespace superpack {

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


}  // namespace superpack
