// First-order forward-mode automatic differentiation over an interval type: a Jet holds an
// enclosure of f(x) and of f'(x) for every x in the box. Writing a formula once as a
// template over its scalar gives its value (scalar I) and its derivative (scalar Jet<I>)
// from the same source, so an equation and its Jacobian cannot disagree.
#pragma once
#include <utility>

#include "superpack/arith/interval.hpp"

namespace superpack {

template <class I>
struct Jet {
    I value;
    I derivative;
};

// The field of a Jet's scalar, so that formulas templated on their parameter (e.g. p) take a Jet.
template <class I>
auto field_of(const Jet<I>& x) {
    return field_of(x.value);
}

// The independent variable (derivative 1) and a constant (derivative 0).
template <class I>
Jet<I> variable(const I& x) {
    return {x, field_of(x).integer(1)};
}
template <class I>
Jet<I> constant(const I& x) {
    return {x, field_of(x).integer(0)};
}

template <class I> Jet<I> operator+(const Jet<I>& a, const Jet<I>& b) { return {a.value + b.value, a.derivative + b.derivative}; }
template <class I> Jet<I> operator-(const Jet<I>& a, const Jet<I>& b) { return {a.value - b.value, a.derivative - b.derivative}; }
template <class I> Jet<I> operator-(const Jet<I>& a) { return {-a.value, -a.derivative}; }
template <class I> Jet<I> operator*(const Jet<I>& a, const Jet<I>& b) {
    return {a.value * b.value, a.derivative * b.value + a.value * b.derivative};
}
template <class I> Jet<I> operator/(const Jet<I>& a, const Jet<I>& b) {
    const I quotient = a.value / b.value;
    return {quotient, (a.derivative - quotient * b.derivative) / b.value};
}
template <class I> Jet<I> operator+(const Jet<I>& a, const I& c) { return {a.value + c, a.derivative}; }
template <class I> Jet<I> operator+(const I& c, const Jet<I>& a) { return {c + a.value, a.derivative}; }
template <class I> Jet<I> operator-(const Jet<I>& a, const I& c) { return {a.value - c, a.derivative}; }
template <class I> Jet<I> operator-(const I& c, const Jet<I>& a) { return {c - a.value, -a.derivative}; }
template <class I> Jet<I> operator*(const Jet<I>& a, const I& c) { return {a.value * c, a.derivative * c}; }
template <class I> Jet<I> operator*(const I& c, const Jet<I>& a) { return {c * a.value, c * a.derivative}; }
template <class I> Jet<I> operator/(const Jet<I>& a, const I& c) { return {a.value / c, a.derivative / c}; }
template <class I> Jet<I> operator/(const I& c, const Jet<I>& a) {
    const I quotient = c / a.value;
    return {quotient, -quotient * a.derivative / a.value};
}

template <class I> Jet<I> exp(const Jet<I>& a) {
    const I value = exp(a.value);
    return {value, value * a.derivative};
}
template <class I> Jet<I> log(const Jet<I>& a) { return {log(a.value), a.derivative / a.value}; }
template <class I> Jet<I> expm1(const Jet<I>& a) {
    const I value = expm1(a.value);
    return {value, (value + field_of(a.value).integer(1)) * a.derivative};
}
template <class I> Jet<I> log1p(const Jet<I>& a) {
    return {log1p(a.value), a.derivative / (field_of(a.value).integer(1) + a.value)};
}
template <class I> Jet<I> sqrt(const Jet<I>& a) {
    const I value = sqrt(a.value);
    return {value, a.derivative / (field_of(value).integer(2) * value)};
}
template <class I> Jet<I> gamma(const Jet<I>& a) {
    const I value = gamma(a.value);
    return {value, value * digamma(a.value) * a.derivative};
}

// |x|^y with a constant exponent y: d/dx = y sign(x) |x|^(y-1). A Jet's derivative must
// bound every slope (f(b) - f(a)) / (b - a) over the box, which is what Newton and Krawczyk
// use. Where x reaches 0 (pow_signed gives the kernel sign(x) |x|^(y-1)):
//   y > 1: the derivative is continuous, bounded, and 0 at x = 0;
//   y = 1 exactly (p = 1/2): |x| has no derivative at 0, but [-1, 1] still bounds every slope,
//     because | |b| - |a| | <= |b - a| (|x| is 1-Lipschitz); the lattice criterion relies on it;
//   y < 1: |x|^y has no finite bound on its slopes near 0, so the derivative is the whole line.
// For a narrow x certainly away from 0, |x|^(y-1) = |x|^y / |x| saves the second power, the
// dearest operation in Newton's inner loop. (On a wide x the quotient would overestimate.)
template <class I> Jet<I> pow_abs(const Jet<I>& x, const I& y) {
    const I value = pow_abs(x.value, y);
    if (narrow_positive(x.value)) return {value, y * (value / x.value) * x.derivative};
    const I one = field_of(y).integer(1);
    return {value, y * pow_signed(x.value, y - one) * x.derivative};
}
// x^y for x >= 0 with a constant exponent: d/dx = y x^(y-1), unbounded near 0 for y < 1
// (pow_nonneg encloses it as [b^(y-1), +inf] on [0, b]; at the point 0 it is +inf).
template <class I> Jet<I> pow_nonneg(const Jet<I>& x, const I& y) {
    const I value = pow_nonneg(x.value, y);
    if (narrow_positive(x.value)) return {value, y * (value / x.value) * x.derivative};
    const I exponent = y - field_of(y).integer(1);
    // At the point 0 with y < 1 the slope is +inf, and pow_nonneg refuses 0^(y-1).
    const bool at_zero = !certainly_positive(upper_point(x.value));
    const I kernel = at_zero && !certainly_nonnegative(exponent) ? unbounded_above(x.value)
                                                                 : pow_nonneg(x.value, exponent);
    return {value, y * kernel * x.derivative};
}
// x^y with both varying, x > 0: exp(y log x).
template <class I> Jet<I> pow_nonneg(const Jet<I>& x, const Jet<I>& y) { return exp(y * log(x)); }
// |x|^y with both varying (d/dp of the contact equations, whose exponent is 2p):
// d = y sign(x) |x|^(y-1) dx + |x|^y log|x| dy. The log term needs x != 0 and is skipped
// when dy is exactly 0, so a constant exponent keeps the |x|^y behaviour at x = 0.
template <class I> Jet<I> pow_abs(const Jet<I>& x, const Jet<I>& y) {
    const I one = field_of(y.value).integer(1);
    const I value = pow_abs(x.value, y.value);
    I derivative = y.value * pow_signed(x.value, y.value - one) * x.derivative;
    if (!(contains_zero(y.derivative) && width_upper(y.derivative) == 0.0))
        derivative = derivative + value * log(abs(x.value)) * y.derivative;
    return {value, derivative};
}

// (1 + u)^k = exp(k log1p(u)) for u > -1, accurate where 1 + u rounds away the digits of u
// (C0, C1 at large p). The Jet forms differentiate as pow_abs does, d = k (1 + u)^(k-1) du
// + (1 + u)^k log1p(u) dk, so that u appears once in each factor and a wide box stays tight.
template <class U, class K> auto pow1p(const U& u, const K& k) { return exp(k * log1p(u)); }
template <class I> Jet<I> pow1p(const Jet<I>& u, const I& k) {
    const I one = field_of(k).integer(1);
    const I value = pow1p(u.value, k);
    if (narrow_positive(one + u.value)) return {value, k * (value / (one + u.value)) * u.derivative};
    return {value, k * pow1p(u.value, k - one) * u.derivative};
}
template <class I> Jet<I> pow1p(const Jet<I>& u, const Jet<I>& k) {
    Jet<I> result = pow1p(u, k.value);
    if (!(contains_zero(k.derivative) && width_upper(k.derivative) == 0.0))
        result.derivative = result.derivative + result.value * log1p(u.value) * k.derivative;
    return result;
}

// Uniform accessors so that generic code can read the value of either scalar.
template <class I> const I& value_of(const Jet<I>& a) { return a.value; }
inline const DInterval& value_of(const DInterval& a) { return a; }
inline const Ball& value_of(const Ball& a) { return a; }
inline double value_of(const double& a) { return a; }
// The field (arith/interval.hpp field_of) of a scalar's value: one Jet<I> and its I share it.
template <class T> auto scalar_field(const T& x) { return field_of(value_of(x)); }

}  // namespace superpack

namespace superpack {
// The integer n as a scalar of the same kind (and precision) as `like`, with no width.
template <class I> I constant_like(const I& like, long n) { return field_of(like).integer(n); }
template <class I> Jet<I> constant_like(const Jet<I>& like, long n) { return constant(field_of(like.value).integer(n)); }
}  // namespace superpack
