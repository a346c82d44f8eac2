#include "checker/core/replay.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "checker/core/limits.hpp"
#include "checker/core/tree_walk.hpp"

namespace superpack_checker {

namespace {

// Floating-point inverse by Gauss-Jordan with partial pivoting: a preconditioner (a guess);
// soundness does not depend on it. False when (numerically) singular.
bool invert(std::vector<std::vector<double>>& a, std::vector<std::vector<double>>& inverse) {
    const std::size_t n = a.size();
    inverse.assign(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) inverse[i][i] = 1.0;
    for (std::size_t column = 0; column < n; ++column) {
        std::size_t pivot = column;
        for (std::size_t row = column + 1; row < n; ++row)
            if (std::fabs(a[row][column]) > std::fabs(a[pivot][column])) pivot = row;
        if (!(std::fabs(a[pivot][column]) > 0.0) || !std::isfinite(a[pivot][column])) return false;
        std::swap(a[pivot], a[column]);
        std::swap(inverse[pivot], inverse[column]);
        const double scale = a[column][column];
        for (std::size_t k = 0; k < n; ++k) {
            a[column][k] /= scale;
            inverse[column][k] /= scale;
        }
        for (std::size_t row = 0; row < n; ++row) {
            if (row == column) continue;
            const double factor = a[row][column];
            for (std::size_t k = 0; k < n; ++k) {
                a[row][k] -= factor * a[column][k];
                inverse[row][k] -= factor * inverse[column][k];
            }
        }
    }
    return true;
}

Real exact_double(double x, mpfr_prec_t precision) {
    return doubles(x, x, precision);  // exact: precision >= 53
}

}  // namespace

bool box_inside(const Box& inner, const Box& outer) {
    for (std::size_t k = 0; k < inner.size(); ++k)
        if (!subset(inner[k], outer[k])) return false;
    return true;
}

namespace {

// The sum of the widths: a stopping rule that sees any component shrink.
Width total_width(const Box& box) {
    Width sum;
    for (const Real& x : box) sum = sum + width(x);
    return sum;
}

// The Krawczyk operator on X = current: K(X) = m - C F(m) + (I - C J(X)) (X - m), with m the
// midpoint, C the inverse of the midpoint Jacobian and J(X) = jacobian; with a parameter, F(m)
// is taken at p0 and its drift C F_p(m, P) (P - p0) subtracted.
Box krawczyk_image(const System& system, const Box& current, const std::vector<std::vector<Real>>& jacobian,
                   const std::vector<std::vector<double>>& inverse, const ParameterForm* parameter) {
    const std::size_t n = current.size();
    const mpfr_prec_t precision = current[0].precision();
    Box center, offset;
    for (const Real& x : current) {
        center.push_back(midpoint(x));
        offset.push_back(x - center.back());
    }
    const std::vector<Real> at_center = parameter ? parameter->value_at_p0(center) : system.value(center);
    const std::vector<Real> slope = parameter ? parameter->derivative(center) : std::vector<Real>();
    Box image;
    for (std::size_t i = 0; i < n; ++i) {
        Real k = center[i];
        Real drift = integer(0, precision);  // (C F_p(m, P))_i
        for (std::size_t j = 0; j < n; ++j) {
            k = k - exact_double(inverse[i][j], precision) * at_center[j];
            if (parameter) drift = drift + exact_double(inverse[i][j], precision) * slope[j];
            Real entry = integer(i == j ? 1 : 0, precision);
            for (std::size_t l = 0; l < n; ++l) entry = entry - exact_double(inverse[i][l], precision) * jacobian[l][j];
            k = k + entry * offset[j];
        }
        if (parameter) k = k - drift * parameter->offset;
        image.push_back(k);
    }
    return image;
}

}  // namespace

KrawczykReplay replay_krawczyk(const System& system, const Box& box, int max_iterations, const ParameterForm* parameter) {
    const std::size_t n = box.size();
    const mpfr_prec_t precision = box[0].precision();
    KrawczykReplay result;
    Box current = box;
    bool exists = false;
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
        const std::vector<Real> values = system.value(current);
        for (const Real& value : values)
            if (excludes_zero(value)) {
                // A root stays in every iterate, so once one is proved this cannot happen.
                result.status = exists ? ReplayStatus::undecided : ReplayStatus::none;
                result.reason = exists ? "inconsistent: a proved root vanished" : "a component of F has one sign";
                return result;
            }
        const std::vector<std::vector<Real>> jacobian = system.jacobian(current);
        std::vector<std::vector<double>> guess(n, std::vector<double>(n)), inverse;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) guess[i][j] = middle(jacobian[i][j]);
        if (!invert(guess, inverse)) {
            result.reason = "midpoint Jacobian singular";
            break;
        }
        const Box image = krawczyk_image(system, current, jacobian, inverse, parameter);
        Box next;
        bool interior = true;
        for (std::size_t i = 0; i < n; ++i) {
            interior = interior && interior_subset(image[i], current[i]);
            Real meet(precision);
            if (!intersect(meet, image[i], current[i])) {
                result.status = exists ? ReplayStatus::undecided : ReplayStatus::none;
                result.reason = exists ? "inconsistent: a proved root vanished" : "K(X) disjoint from X";
                return result;
            }
            next.push_back(meet);
        }
        exists = exists || interior;
        const Width before = total_width(current), after = total_width(next);
        current = next;
        if (exists && (after == 0.0 || after >= 0.75 * before)) break;
        if (!exists && after >= before) {
            result.reason = "Krawczyk operator did not contract";
            break;
        }
    }
    if (exists) {
        result.status = ReplayStatus::unique;
        result.root = current;
        result.reason = "K(X) in the interior of X";
    } else if (result.reason.empty()) {
        result.reason = "iteration budget exhausted";
    }
    return result;
}

Real replay_newton(Context& context, const std::function<Real(const Real&)>& f,
                   const std::function<Real(const Real&)>& derivative, const Real& box, const Real& center,
                   const Real* stored_derivative, const Real* stored_image, const std::string& path) {
    context.current_step = path;
    context.require(subset(center, box), path + ".midpoint", "the midpoint is not in the box");
    const Real slope = derivative(box);
    context.require(excludes_zero(slope), path + ".derivative", "f'(X) may contain 0: checker's f'(X) = " + text(slope));
    if (stored_derivative)
        context.require(subset(slope, *stored_derivative), path + ".derivative",
                        "the stored f'(X) " + text(*stored_derivative) + " does not contain the checker's " + text(slope));
    const Real image = center - f(center) / slope;
    if (stored_image)
        context.require(subset(image, *stored_image), path + ".image",
                        "the stored N(X) " + text(*stored_image) + " does not contain the checker's " + text(image));
    // f' != 0 on X: at most one root in X, and every root of X stays in each iterate
    // X_(k+1) = N(X_k) ∩ X_k. N(X_k) in int X_k proves one exists. For a point p this holds at
    // k = 0; for an interval of p (an audit piece) f(m) is wide and a few iterates may be needed.
    Real current(box.precision());
    context.require(intersect(current, image, box), path + ".image", "N(X) is disjoint from X: no root in X");
    bool exists = interior_subset(image, box);
    for (int iteration = 0; iteration < 60 && !exists; ++iteration) {
        const Real mid = midpoint(current);
        const Real next_image = mid - f(mid) / derivative(current);
        exists = interior_subset(next_image, current);
        Real next(box.precision());
        context.require(intersect(next, next_image, current), path + ".image", "a Newton iterate is empty: no root in X");
        if (!exists && width(next) >= width(current)) break;
        current = next;
    }
    context.require(exists, path + ".image",
                    "N(X) = " + text(image) + " is not in the interior of X = " + text(box) + ", nor is any later iterate");
    for (int iteration = 0; iteration < 200; ++iteration) {
        const Real mid = midpoint(current);
        const Real next_image = mid - f(mid) / derivative(current);
        Real next(box.precision());
        context.require(intersect(next, next_image, current), path, "a Newton iterate lost the root (inconsistent)");
        const Width before = width(current), after = width(next);
        current = next;
        if (after == 0.0 || after >= 0.75 * before) break;
    }
    return current;
}

namespace {

// A split whose two children are still to replay: what checking that they cover its box needs.
struct SplitCover {
    std::string path;
    Box box;
    std::size_t dimension = 0;
    Box left, right;  // the children's boxes, written when each is replayed
};

// A step of the walk: a node to replay (its box goes to `box`, read by its parent's cover
// check), or, with no node, the cover check of `split`, once both its children are replayed.
struct PartitionStep {
    const Json* node = nullptr;
    std::string path;
    int depth = 0;
    Box* box = nullptr;
    std::shared_ptr<SplitCover> split;
};

// The two children cover the box: along `dimension` they reach its ends and meet (or overlap),
// along the others each holds the box's whole side.
void check_cover(Context& context, const SplitCover& split) {
    const Box& box = split.box;
    const Box& left = split.left;
    const Box& right = split.right;
    const std::size_t dimension = split.dimension;
    const std::string left_path = split.path + ".cases[0]", right_path = split.path + ".cases[1]";
    context.require(left.size() == box.size() && right.size() == box.size(), split.path, "children of another dimension");
    const Real& side = box[dimension];
    context.require(mpfr_cmp(left[dimension].lo(), side.lo()) <= 0, left_path + ".box",
                    "the first case does not reach the lower end of its parent");
    context.require(mpfr_cmp(right[dimension].hi(), side.hi()) >= 0, right_path + ".box",
                    "the second case does not reach the upper end of its parent");
    context.require(mpfr_cmp(left[dimension].hi(), right[dimension].lo()) >= 0, right_path + ".box",
                    "a gap between the two cases of the split");
    for (std::size_t k = 0; k < box.size(); ++k) {
        if (k == dimension) continue;
        context.require(subset(box[k], left[k]), left_path + ".box", "the case does not hold its parent's side");
        context.require(subset(box[k], right[k]), right_path + ".box", "the case does not hold its parent's side");
    }
}

// One node: a leaf is handed to `leaf`; a split pushes its cover check, then its two cases.
void replay_partition_step(Context& context, PartitionStep& step, std::vector<PartitionStep>& stack, const LeafCheck& leaf) {
    if (!step.node) {
        check_cover(context, *step.split);
        return;
    }
    const Json& node = *step.node;
    const std::string& path = step.path;
    if (step.depth > max_proof_depth)
        context.malformed(path, "a proof tree deeper than " + std::to_string(max_proof_depth) + " splits (max_proof_depth)");
    const Box box = context.box(context.member(node, "box", path), path + ".box");
    *step.box = box;
    if (context.string_at(node, "kind", path) != "split") {
        context.current_step = path;
        leaf(node, box, path);
        return;
    }
    const Json& cases = context.member(node, "cases", path);
    if (!cases.is_array()) context.malformed(path + ".cases", "expected an array");
    context.require(cases.size() == 2, path + ".cases", "a split needs both of its cases");
    const auto dimension = static_cast<std::size_t>(read_integer(context, context.member(node, "dimension", path),
                                                                 path + ".dimension", 0, static_cast<long>(box.size()) - 1));
    auto split = std::make_shared<SplitCover>(SplitCover{path, box, dimension, {}, {}});
    stack.push_back({nullptr, {}, 0, nullptr, split});
    stack.push_back({&cases[1], path + ".cases[1]", step.depth + 1, &split->right, nullptr});
    stack.push_back({&cases[0], path + ".cases[0]", step.depth + 1, &split->left, nullptr});
}

}  // namespace

Box check_partition(Context& context, const Json& node, const std::string& path, const LeafCheck& leaf) {
    Box root;
    walk_tree(PartitionStep{&node, path, 0, &root, nullptr},
              [&](PartitionStep& step, std::vector<PartitionStep>& stack) { replay_partition_step(context, step, stack, leaf); });
    return root;
}

void check_root_leaf(Context& context, const System& system, const Json& leaf, const Box& box,
                     const std::string& path, std::vector<Box>* roots) {
    const std::string kind = context.string_at(leaf, "kind", path);
    if (kind == "excluded") {
        const Box stored = context.box(context.member(leaf, "values", path), path + ".values");
        const std::vector<Real> own = system.value(box);
        context.require(stored.size() == own.size(), path + ".values", "wrong number of components");
        bool one_signed = false;
        for (std::size_t i = 0; i < own.size(); ++i) {
            context.require(subset(own[i], stored[i]), path + ".values[" + std::to_string(i) + "]",
                            "the stored value " + text(stored[i]) + " does not contain the checker's " + text(own[i]));
            one_signed = one_signed || excludes_zero(own[i]);
        }
        context.require(one_signed, path, "no component of F has one sign on the box");
        return;
    }
    if (kind != "krawczyk") context.malformed(path + ".kind", "unknown leaf kind \"" + kind + "\"");
    const std::string status = context.string_at(leaf, "status", path);
    const KrawczykReplay replay = replay_krawczyk(system, box, 80);
    if (status == "none") {
        context.require(replay.status == ReplayStatus::none, path,
                        "the checker could not prove the box free of roots (" + replay.reason + ")");
        return;
    }
    if (status != "unique") context.malformed(path + ".status", "expected none or unique");
    context.require(replay.status == ReplayStatus::unique, path,
                    "the checker could not prove exactly one root in the box (" + replay.reason + ")");
    const Box stored_root = context.box(context.member(leaf, "root", path), path + ".root");
    context.require(stored_root.size() == box.size(), path + ".root", "wrong dimension");
    for (std::size_t k = 0; k < box.size(); ++k)
        context.require(subset(replay.root[k], stored_root[k]), path + ".root[" + std::to_string(k) + "]",
                        "the stored root box " + text(stored_root[k]) + " does not hold the root " + text(replay.root[k]));
    if (roots) roots->push_back(replay.root);
}

void check_encloses(Context& context, const Json& stated, const std::string& path, const Real& own) {
    const Real claimed = context.interval(stated, path);
    context.require(subset(own, claimed), path,
                    "the stated enclosure " + text(claimed) + " does not contain the checker's " + text(own));
    // Containing the checker's value is not enough: phi widened to [0.80, 1.61] still contains it,
    // and the sentence prints what the file states. So the stated enclosure may be only a little
    // wider than the checker's own, plus the producer's rounding (limits.hpp). Part of the same
    // step: the count of steps is that of the containment check.
    const Width allowed = enclosure_width_factor * width(own) +
                          scaled(magnitude(own), enclosure_slack_bits - context.producer_precision());
    if (!(width(claimed) <= allowed)) {
        std::ostringstream reason;
        reason << "wider than the checker's own enclosure " << text(own) << ": " << text(claimed) << " is " << width(claimed)
               << " wide, more than " << enclosure_width_factor << " times the checker's width plus 2^-(bits - "
               << enclosure_slack_bits << ") max(1, |x|), " << allowed;
        context.reject(path, reason.str());
    }
}

bool disjoint(const Box& a, const Box& b) {
    for (std::size_t k = 0; k < a.size(); ++k)
        if (less(a[k], b[k]) || less(b[k], a[k])) return true;
    return false;
}

}  // namespace superpack_checker
