// The superball |x1|^2p + ... + |xd|^2p <= 1 in dimension d: its volume and its gauge.
#pragma once
#include <vector>

#include "superpack/arith/jet.hpp"

namespace superpack {

// Volume of the unit ball of the l_q norm in R^d, q = 2p:
//   V_d(p) = (2 Gamma(1 + 1/(2p)))^d / Gamma(1 + d/(2p)).
// d = 3 is the paper's V_sb(p) (Eq. 4; NOTES.md shows the two forms agree), d = 2 the
// superdisk area 4 Gamma(1 + 1/(2p))^2 / Gamma(1 + 1/p). T is an interval or a Jet (d/dp).
template <class T>
T enclose_ball_volume(const T& p, int dimension) {
    const auto field = scalar_field(p);
    const auto one = field.integer(1);
    const T inverse_q = one / (field.integer(2) * p);
    const T side = field.integer(2) * gamma(inverse_q + one);
    T power = side;
    for (int k = 1; k < dimension; ++k) power = power * side;
    return power / gamma(field.integer(dimension) * inverse_q + one);
}

// sum_i |x_i|^(2p): the 2p-th power of the gauge. A translate by u of the body K meets
// K + v in interior points iff this is < 2^(2p) for u - v (NOTES.md, "Packing criterion").
template <class T, class I>
T gauge_power(const std::vector<T>& x, const I& two_p) {
    T sum = pow_abs(x[0], two_p);
    for (std::size_t i = 1; i < x.size(); ++i) sum = sum + pow_abs(x[i], two_p);
    return sum;
}

template <class Field>
typename Field::Interval enclose_superball_volume(const Rational& p, const Field& field) {
    return enclose_ball_volume(field.rational(p), 3);
}

template <class Field>
typename Field::Interval enclose_superdisk_area(const Rational& p, const Field& field) {
    return enclose_ball_volume(field.rational(p), 2);
}

}  // namespace superpack
