#include "checker/formulas/smallest_root.hpp"

#include <memory>
#include <stdexcept>

#include "checker/core/replay.hpp"
#include "checker/formulas/equations_crossover.hpp"

namespace superpack_checker {

namespace {
std::unique_ptr<Real> optional_interval(Context& context, const Json& node, const std::string& key, const std::string& path) {
    const Json* value = context.optional_member(node, key);
    if (!value) return nullptr;
    return std::make_unique<Real>(context.interval(*value, path + "." + key));
}
// Interval Newton from a bare box: f' excludes 0 on X (at most one root in X), and some
// iterate X_k (X_{k+1} = N(X_k) ∩ X_k, which keeps every root of X) has N(X_k) inside its
// interior: exactly one root. The producer may need a few contractions before that happens.
Real newton_from_box(Context& context, const CubicEquation& equation, const Real& box, const std::string& path) {
    context.current_step = path;
    const Real slope = equation.derivative(box);
    context.require(excludes_zero(slope), path + ".box", "f' may vanish on the box: " + text(slope));
    Real current = box;
    bool exists = false;
    for (int iteration = 0; iteration < 200; ++iteration) {
        const Real center = midpoint(current);
        const Real image = center - equation.value(center) / equation.derivative(current);
        exists = exists || interior_subset(image, current);
        Real next(box.precision());
        context.require(intersect(next, image, current), path + ".box", "no root in the box (Newton image disjoint)");
        const Width before = width(current), after = width(next);
        current = next;
        if (after == 0.0 || after >= 0.75 * before) break;
    }
    context.require(exists, path + ".box", "Newton did not prove a root in the box");
    return current;
}

}  // namespace

Real replay_smallest_root(Context& context, const CubicEquation& equation, const Json& node, const std::string& path) {
    const Real box = context.interval(context.member(node, "box", path), path + ".box");
    const auto center = optional_interval(context, node, "midpoint", path);
    const auto derivative = optional_interval(context, node, "derivative", path);
    const auto image = optional_interval(context, node, "image", path);
    const auto stored_root = optional_interval(context, node, "root", path);
    auto value = [&](const Real& x) { return equation.value(x); };
    auto derivative_of = [&](const Real& x) { return equation.derivative(x); };
    const Real s = center ? replay_newton(context, value, derivative_of, box, *center, derivative.get(), image.get(), path)
                          : newton_from_box(context, equation, box, path);
    context.require(positive(s), path + ".root", "the root may not be positive: " + text(s));
    if (stored_root)
        context.require(subset(s, *stored_root), path + ".root",
                        "the stored root " + text(*stored_root) + " does not hold the checker's " + text(s));
    const Real below = hull(integer(0, box.precision()), upper_point(box));
    context.require(positive(cubic_slope_in_s(equation, below)), path,
                    "f is not proved increasing on [0, upper end of the box]: s may not be the smallest positive root");
    return s;
}

Real refine_known_root(const CubicEquation& equation, const Real& box) {
    Real current = box;
    for (int iteration = 0; iteration < 100; ++iteration) {
        const Real center = midpoint(current);
        const Real image = center - equation.value(center) / equation.derivative(current);
        Real next(box.precision());
        if (!intersect(next, image, current)) throw std::domain_error("a Newton iterate lost the root of the contact equation");
        const Width before = width(current), after = width(next);
        current = next;
        if (after == 0.0 || after >= 0.75 * before) break;
    }
    return current;
}

}  // namespace superpack_checker
