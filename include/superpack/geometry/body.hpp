// A body of superpack: the superball K = {x in R^d : |x_1|^(2p) + ... + |x_d|^(2p) <= 1}
// (d = 3; the superdisk for d = 2), with exact p. What packing code asks of a body: is it
// convex, is a point inside it, its gauge, its support function h_K(u) = max over x in K of
// <u, x>, and the point where that maximum is attained.
//
// Write q = 2p. For q >= 1 the gauge ||x||_q is a norm and K is convex; for q < 1 (p < 1/2)
// K is a star body, ||x||_q only a quasi-norm, and conv K is the cross-polytope (the l_1
// ball: K contains its vertices +-e_i and lies inside it, since ||x||_1 <= ||x||_q for q <= 1).
// Support function: for q > 1, h_K(u) = ||u||_r with the dual exponent r = q / (q - 1)
// (Hoelder's inequality, with equality at the support point below); for q <= 1,
// h_K(u) = h_conv K(u) = max_i |u_i|.
#pragma once
#include <vector>

#include "superpack/arith/exact.hpp"
#include "superpack/arith/outcome.hpp"
#include "superpack/geometry/superball.hpp"

namespace superpack {

struct Superball {
    int dimension = 3;
    Rational p;
    // Convex exactly when 2p >= 1.
    bool convex() const { return 2 * p >= 1; }
    // r = 2p / (2p - 1), the exponent of the dual norm; requires 2p > 1.
    Rational dual_exponent() const;
};

// A superball of dimension 2 or 3 with p > 0; throws InputError otherwise.
Superball make_superball(int dimension, const Rational& p);

namespace body_detail {
template <class I>
I larger(const I& a, const I& b) {
    if (certainly_less(a, b)) return b;
    if (certainly_less(b, a)) return a;
    return hull(a, b);  // holds max(a, b) for every choice of a and b
}
template <class I>
I two_p_of(const Superball& body, const I& like) {
    return field_of(like).rational(2 * body.p);
}
}  // namespace body_detail

// Is x in the interior of K (sum |x_i|^(2p) < 1)? refuted means x lies on the boundary or outside.
template <class I>
Outcome in_interior(const Superball& body, const std::vector<I>& x) {
    const I power = gauge_power(x, body_detail::two_p_of(body, x[0]));
    const I one = field_of(x[0]).integer(1);
    if (certainly_less(power, one)) return Outcome::proved;
    if (certainly_nonnegative(power - one)) return Outcome::refuted;
    return Outcome::undecided;
}

// Is x in K (sum |x_i|^(2p) <= 1)? refuted means x lies outside.
template <class I>
Outcome in_body(const Superball& body, const std::vector<I>& x) {
    const I power = gauge_power(x, body_detail::two_p_of(body, x[0]));
    const I one = field_of(x[0]).integer(1);
    if (certainly_nonnegative(one - power)) return Outcome::proved;
    if (certainly_less(one, power)) return Outcome::refuted;
    return Outcome::undecided;
}

// The gauge ||x||_(2p) = (sum |x_i|^(2p))^(1/(2p)): the smallest t >= 0 with x in tK.
template <class I>
I gauge(const Superball& body, const std::vector<I>& x) {
    const auto field = field_of(x[0]);
    return pow_nonneg(gauge_power(x, body_detail::two_p_of(body, x[0])), field.rational(1 / (2 * body.p)));
}

// h_K(u) = max over x in K of <u, x>, for every u in the box.
template <class I>
I support_function(const Superball& body, const std::vector<I>& u) {
    const auto field = field_of(u[0]);
    if (2 * body.p <= 1) {
        I result = abs(u[0]);
        for (std::size_t i = 1; i < u.size(); ++i) result = body_detail::larger(result, abs(u[i]));
        return result;
    }
    const Rational r = body.dual_exponent();
    I sum = pow_abs(u[0], field.rational(r));
    for (std::size_t i = 1; i < u.size(); ++i) sum = sum + pow_abs(u[i], field.rational(r));
    return pow_nonneg(sum, field.rational(1 / r));
}

// For 2p > 1 and u != 0: the point of bd K where <u, x> = h_K(u),
// x_i = sign(u_i) |u_i|^(r-1) / h_K(u)^(r-1). Throws std::domain_error for 2p <= 1 (the
// maximum is then attained at a vertex +-e_i, or along a face, and not by this formula).
template <class I>
std::vector<I> support_point(const Superball& body, const std::vector<I>& u) {
    if (2 * body.p <= 1) throw std::domain_error("support_point: needs 2p > 1 (a strictly convex body)");
    const auto field = field_of(u[0]);
    const I r_minus_one = field.rational(body.dual_exponent() - 1);
    const I scale = pow_nonneg(support_function(body, u), r_minus_one);
    std::vector<I> x;
    for (const I& ui : u) x.push_back(pow_signed(ui, r_minus_one) / scale);
    return x;
}

}  // namespace superpack
