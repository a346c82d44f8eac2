// Certified root isolation in n dimensions: the Krawczyk operator.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "superpack/arith/jet.hpp"
#include "superpack/solve/approximate_inverse.hpp"
#include "superpack/solve/root_status.hpp"

namespace superpack {

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
// The interval part is written with plain loops over std::vector rather than a matrix
// library's matrices of intervals: those need Scalar(0) conversions and a default-constructed
// scalar, and a Ball has no meaningful precision until it is made from a field.
// C v for the floating-point matrix C and an interval vector v.
template <class I>
std::vector<I> precondition(const DoubleMatrix& inverse, const std::vector<I>& v) {
    const auto field = field_of(v[0]);
    std::vector<I> result;
    for (std::size_t i = 0; i < v.size(); ++i) {
        I sum = field.integer(0);
        for (std::size_t j = 0; j < v.size(); ++j) sum = sum + from_doubles(field.integer(0), inverse(i, j), inverse(i, j)) * v[j];
        result.push_back(sum);
    }
    return result;
}

namespace detail {

// The Jacobian J(X) of f over the box X, one column per seeded variable (a step of the
// iteration of its own: K(X) uses it, and C is the inverse of its midpoints).
template <class I, class F, class Field>
std::vector<std::vector<I>> jacobian_over(const F& f, const std::vector<I>& current, const Field& field) {
    const std::size_t n = current.size();
    std::vector<std::vector<I>> jacobian(n, std::vector<I>(n, field.integer(0)));
    for (std::size_t j = 0; j < n; ++j) {
        std::vector<Jet<I>> seeded;
        for (std::size_t k = 0; k < n; ++k) seeded.push_back(k == j ? variable(current[k]) : constant(current[k]));
        const std::vector<Jet<I>> column = f(seeded);
        for (std::size_t i = 0; i < n; ++i) jacobian[i][j] = column[i].derivative;
    }
    return jacobian;
}

// Whether every entry of J(X) is bounded: an unbounded entry (a power below 1 at 0) bounds no
// contraction (its own step: the iteration gives up on it before inverting).
template <class I>
bool all_bounded(const std::vector<std::vector<I>>& jacobian) {
    for (const std::vector<I>& row : jacobian)
        for (const I& entry : row)
            if (!bounded(entry)) return false;
    return true;
}

// C, a floating-point inverse of the midpoint Jacobian; nothing when it is singular (its own
// step: any C is sound, so it is computed in floating point apart from the interval part).
template <class I>
std::optional<DoubleMatrix> midpoint_inverse(const std::vector<std::vector<I>>& jacobian) {
    const std::size_t n = jacobian.size();
    DoubleMatrix middle(n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) middle(i, j) = mid_double(jacobian[i][j]);
    return approximate_inverse(middle);
}

// K(X) and what it shows of X: within its interior (a unique zero), or disjoint from it (none).
template <class I>
struct KrawczykImage {
    std::vector<I> image;
    bool interior = true, disjoint = false;
};

// K(X) = m - C f(m) + (Id - C J(X)) (X - m), given the preconditioned residual C f(m) and the
// offset X - m (its own step: the operator itself, apart from the iteration around it).
template <class I, class Field>
KrawczykImage<I> krawczyk_image(const std::vector<I>& current, const std::vector<I>& center, const std::vector<I>& offset,
                                const std::vector<I>& preconditioned, const DoubleMatrix& inverse,
                                const std::vector<std::vector<I>>& jacobian, const Field& field) {
    const std::size_t n = current.size();
    KrawczykImage<I> result;
    for (std::size_t i = 0; i < n; ++i) {
        I k = center[i] - preconditioned[i];
        for (std::size_t j = 0; j < n; ++j) {
            // Row i of (Id - C J(X)).
            I entry = field.integer(i == j ? 1 : 0);
            for (std::size_t l = 0; l < n; ++l)
                entry = entry - from_doubles(field.integer(0), inverse(i, l), inverse(i, l)) * jacobian[l][j];
            k = k + entry * offset[j];
        }
        result.image.push_back(k);
        result.interior = result.interior && interior_contains(current[i], k);
        I meet = k;
        if (!intersect(meet, k, current[i])) result.disjoint = true;
    }
    return result;
}

// X becomes X ∩ K(X); returns whether that stopped paying: the new width is at most
// target_width, or more than half the old one (its own step: the iteration's narrowing and
// its stopping rule).
template <class I>
bool narrow_to_image(std::vector<I>& current, const std::vector<I>& image, double target_width) {
    double before = 0, after = 0;
    for (std::size_t i = 0; i < current.size(); ++i) {
        before = std::max(before, width_upper(current[i]));
        I meet = image[i];
        intersect(meet, image[i], current[i]);
        current[i] = meet;
        after = std::max(after, width_upper(current[i]));
    }
    return after <= target_width || after >= 0.5 * before;
}

}  // namespace detail

// The same operator with the preconditioned residual C f(m) supplied by `residual(m, C)`, an
// enclosure of C f(m) (for a family f(x, p) over an interval of p, a mean-value form in p keeps
// the cancellation that C f(m, P) loses: krawczyk_isolate_in_parameter below).
template <class I, class F, class R>
KrawczykResult<I> krawczyk_isolate_with_residual(const F& f, const R& residual, const std::vector<I>& box,
                                                 double target_width, int max_iterations) {
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
        const std::vector<std::vector<I>> jacobian = detail::jacobian_over(f, current, field);
        if (!detail::all_bounded(jacobian)) {
            if (!result.existence) result.reason = "Jacobian unbounded on the box";
            return result;
        }
        const std::optional<DoubleMatrix> inverse = detail::midpoint_inverse(jacobian);
        if (!inverse) {
            result.reason = "midpoint Jacobian singular";
            return result;
        }
        std::vector<I> center, offset;
        for (std::size_t k = 0; k < n; ++k) {
            center.push_back(midpoint(current[k]));
            offset.push_back(current[k] - center[k]);
        }
        const std::vector<I> preconditioned = residual(center, *inverse);
        const detail::KrawczykImage<I> contraction = detail::krawczyk_image(current, center, offset, preconditioned, *inverse, jacobian, field);
        if (contraction.disjoint) {
            if (!result.existence) {
                result.status = RootStatus::none;
                result.reason = "K(X) disjoint from X";
            }
            return result;
        }
        if (contraction.interior && !result.existence) {
            result.existence = result.uniqueness = true;
            result.status = RootStatus::unique;
            result.reason = "K(X) in interior of X";
        }
        const bool settled = detail::narrow_to_image(current, contraction.image, target_width);
        result.box = current;
        if (result.existence && settled) break;
    }
    if (!result.existence) result.reason = "Krawczyk operator did not contract into the box";
    return result;
}

template <class I, class F>
KrawczykResult<I> krawczyk_isolate(const F& f, const std::vector<I>& box, double target_width, int max_iterations) {
    auto residual = [&](const std::vector<I>& center, const DoubleMatrix& inverse) { return precondition(inverse, f(center)); };
    return krawczyk_isolate_with_residual(f, residual, box, target_width, max_iterations);
}

// Does `box` hold exactly one root of f, lying in `previous`? The link of a continuation: when
// the root in `previous` is unique there too, both boxes hold the same root.
template <class I, class F>
bool unique_root_within(const F& f, const std::vector<I>& box, const std::vector<I>& previous) {
    const KrawczykResult<I> root = krawczyk_isolate(f, box, 0.0, 60);
    if (root.status != RootStatus::unique) return false;
    for (std::size_t k = 0; k < box.size(); ++k)
        if (!contains(previous[k], root.box[k])) return false;
    return true;
}

// Krawczyk for f(x, p) = 0 with p in an interval P, proving that for EVERY p in P the box holds
// exactly one root. K(X, P) = m - C f(m, P) + (I - C J(X, P)) (X - m) is sound but useless on
// an ill-conditioned system: C f(m, P) is wide by |C| |f_p| w, not |C f_p| w. The mean-value form
// f(m, p) in f(m, p0) + f_p(m, P) (p - p0) for p in P, with C f(m, p0) and C f_p(m, P) formed first
// and only then times (P - p0), keeps that cancellation. `f` takes (x, p) with x a vector of I or
// Jet<I> and p an I or a Jet<I> (the derivative in p: x constant, p the variable); p0 in P.
template <class I, class F>
KrawczykResult<I> krawczyk_isolate_in_parameter(const F& f, const std::vector<I>& box, const I& p, const I& p0,
                                                double target_width, int max_iterations) {
    auto at_p = [&](const auto& x) { return f(x, p); };
    auto residual = [&](const std::vector<I>& center, const DoubleMatrix& inverse) {
        std::vector<Jet<I>> fixed;
        for (const I& x : center) fixed.push_back(constant(x));
        std::vector<I> slope;
        for (const Jet<I>& value : f(fixed, variable(p))) slope.push_back(value.derivative);
        std::vector<I> result = precondition(inverse, f(center, p0));
        const std::vector<I> drift = precondition(inverse, slope);
        const I offset = p - p0;
        for (std::size_t i = 0; i < result.size(); ++i) result[i] = result[i] + drift[i] * offset;
        return result;
    };
    return krawczyk_isolate_with_residual(at_p, residual, box, target_width, max_iterations);
}

}  // namespace superpack
