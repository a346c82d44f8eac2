#include "checker/formulas/equations.hpp"

namespace superpack_checker {

namespace {
Real one_like(const Real& x) { return integer(1, x.precision()); }
Real two_p(const Real& p) { return 2 * p; }
// b^(-1/(2p)) for a positive integer b.
Real root_of_inverse(long b, const Real& p) { return exp(-log(integer(b, p.precision())) / two_p(p)); }
}  // namespace

Real CubicEquation::shift() const { return root_of_inverse(2, p); }

// (s + t)^k for s > -t, k = 2p or 2p - 1, as exp(k log1p(s - (1 - t))) with 1 - t =
// -expm1(-ln2/(2p)): s + t rounded near 1 would cost log2(2p) bits at large p (s ~ ln2/(2p)).
Real CubicEquation::shifted_power(const Real& s, bool lowered) const {
    const Real k = lowered ? two_p(p) - one_like(p) : two_p(p);
    const Real deficit = -expm1(-log(integer(2, p.precision())) / two_p(p));
    return exp(k * log1p(s - deficit));
}

Real CubicEquation::value(const Real& s) const {
    const Real e = two_p(p);
    const Real sum = shifted_power(s, false);
    if (c1) return sum + 2 * pow_abs(s, e) - one_like(p);
    return sum + pow_abs(s, e) + exp(-e * log(integer(2, p.precision()))) - one_like(p);
}

// d/ds |u|^(2p) = 2p sign(u) |u|^(2p-1), with u = s + t > 0 in the first term.
Real CubicEquation::derivative(const Real& s) const {
    const Real e = two_p(p), e1 = two_p(p) - one_like(p);
    const Real shifted = e * shifted_power(s, true);
    return shifted + (c1 ? 2 : 1) * (e * pow_signed(s, e1));
}

Real OctahedralEquations::l() const { return root_of_inverse(3, p); }

std::array<Real, 2> OctahedralEquations::value(const std::array<Real, 2>& x) const {
    const Real e = two_p(p), ell = l(), one = one_like(p);
    const Real& q = x[0];
    const Real& s = x[1];
    return {2 * pow_abs(q, e) + pow_abs(s, e) - one, pow_abs(q + ell, e) + pow_abs(s - ell, e) + pow_abs(ell - q, e) - one};
}

std::array<std::array<Real, 2>, 2> OctahedralEquations::jacobian(const std::array<Real, 2>& x) const {
    const Real e = two_p(p), e1 = two_p(p) - one_like(p), ell = l();
    const Real& q = x[0];
    const Real& s = x[1];
    return {{{2 * (e * pow_signed(q, e1)), e * pow_signed(s, e1)},
             {e * (pow_signed(q + ell, e1) - pow_signed(ell - q, e1)), e * pow_signed(s - ell, e1)}}};
}

std::array<Real, 3> D14Equations::value(const std::array<Real, 3>& v) const {
    const Real e = two_p(p), one = one_like(p);
    const Real &x = v[0], &y = v[1], &z = v[2];
    return {pow_abs(x, e) + pow_abs(y, e) + pow_abs(z, e) - one,
            pow_abs(x - y, e) + pow_abs(z - x, e) + pow_abs(y + z, e) - one, 3 * pow_abs(y + z - x, e) - one};
}

// d/du |u|^(2p) = 2p sign(u) |u|^(2p-1), by the chain rule through each linear argument.
std::array<std::array<Real, 3>, 3> D14Equations::jacobian(const std::array<Real, 3>& v) const {
    const Real e = two_p(p), e1 = two_p(p) - one_like(p);
    const Real &x = v[0], &y = v[1], &z = v[2];
    const Real a = e * pow_signed(x - y, e1), b = e * pow_signed(z - x, e1), c = e * pow_signed(y + z, e1);
    const Real s = 3 * (e * pow_signed(y + z - x, e1));
    return {{{e * pow_signed(x, e1), e * pow_signed(y, e1), e * pow_signed(z, e1)}, {a - b, c - a, b + c}, {-s, s, s}}};
}

Matrix3 c0_basis(const Real& s, const Real& t) {
    const Real zero(s.precision()), one = one_like(s);
    const Real side = 2 * t;
    return {{{side, side, zero}, {zero, zero, 2 * one}, {-(2 * s), 2 * (s + t), one}}};
}

Matrix3 c1_basis(const Real& s, const Real& t) {
    const Real zero(s.precision());
    const Real side = 2 * t;
    return {{{side, side, zero}, {side, zero, side}, {2 * (s + t), -(2 * s), -(2 * s)}}};
}

Real o0_height(const Real& p) {
    const Real one = one_like(p);
    const Real base = one - exp((one - two_p(p)) * log(integer(2, p.precision())));
    return pow_abs(base, one / two_p(p));
}

Matrix3 o0_basis(const Real& c) {
    const Real zero(c.precision()), one = one_like(c), two = integer(2, c.precision());
    return {{{two, zero, zero}, {zero, two, zero}, {one, one, 2 * c}}};
}

Matrix3 o1_basis(const Real& q, const Real& s, const Real& l) {
    const Real side = 2 * l;
    return {{{side, side, -side}, {-(2 * q), 2 * s, -(2 * q)}, {2 * q, -(2 * q), -(2 * s)}}};
}

Matrix3 d14_basis(const Real& x, const Real& y, const Real& z) {
    const Real a = 2 * x, b = 2 * y, c = 2 * z;
    return {{{-a, b, c}, {c, -a, b}, {b, c, -a}}};
}

Real determinant(const Matrix3& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Real lattice_norm(const std::array<Real, 3>& v, const Real& two_p) {
    const Real half = one_like(two_p) / integer(2, two_p.precision());
    const Real sum = pow_abs(half * v[0], two_p) + pow_abs(half * v[1], two_p) + pow_abs(half * v[2], two_p);
    return integer(2, two_p.precision()) * pow_abs(sum, one_like(two_p) / two_p);
}

Real superball_volume(const Real& p) {
    const Real one = one_like(p);
    const Real inverse = one / two_p(p);
    const Real side = 2 * gamma(one + inverse);
    return side * side * side / gamma(one + 3 * inverse);
}

}  // namespace superpack_checker
