#include "checker/formulas/equations_superdisk.hpp"

#include <stdexcept>

namespace superpack_checker {

namespace {
Real one_like(const Real& x) { return integer(1, x.precision()); }
}  // namespace

Real SuperdiskEquations::exponent() const { return 2 * p; }

Real SuperdiskEquations::boundary_x(const Real& t) const {
    const Real q = exponent(), one = one_like(p);
    return one / pow_abs(one + pow_abs(t, q), one / q);
}

Real SuperdiskEquations::boundary_x_derivative(const Real& t) const {
    const Real q = exponent(), one = one_like(p);
    return -(pow_abs(boundary_x(t), q + one) * pow_signed(t, q - one));
}

std::array<Real, 2> SuperdiskEquations::contact(const Real& a, const Real& b, const Real& t) const {
    const Real q = exponent(), one = one_like(p);
    const Real x = boundary_x(t);
    return {pow_abs(a, q) + pow_abs(b, q) - one, pow_abs(a - x, q) + pow_abs(b - t * x, q) - one};
}

std::array<std::array<Real, 2>, 2> SuperdiskEquations::jacobian(const Real& a, const Real& b, const Real& t) const {
    const Real q = exponent(), q1 = exponent() - one_like(p);
    const Real x = boundary_x(t);
    return {{{q * pow_signed(a, q1), q * pow_signed(b, q1)}, {q * pow_signed(a - x, q1), q * pow_signed(b - t * x, q1)}}};
}

Real SuperdiskEquations::determinant(const Real& a, const Real& b, const Real& t) const {
    return boundary_x(t) * (b - t * a);
}

Real SuperdiskEquations::derivative(const Real& a, const Real& b, const Real& t) const {
    const Real q = exponent(), q1 = exponent() - one_like(p);
    const Real x = boundary_x(t), dx = boundary_x_derivative(t);
    const Real dy = x + t * dx;  // d(t x)/dt
    const auto j = jacobian(a, b, t);
    // dF1/dt = q sign(a - x)|a - x|^(q-1) (-x') + q sign(b - t x)|b - t x|^(q-1) (-(t x)'); dF0/dt = 0.
    const Real f1_t = -(j[1][0] * dx) - j[1][1] * dy;
    const Real jacobian_determinant = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    if (!excludes_zero(jacobian_determinant)) throw std::domain_error("the Jacobian of the contact system may vanish");
    const Real da = j[0][1] * f1_t / jacobian_determinant;     // a'
    const Real db = -(j[0][0] * f1_t) / jacobian_determinant;  // b'
    // D = x b - t x a: D_t = x' b - (x + t x') a, D_a = -t x, D_b = x.
    return dx * b - dy * a - t * x * da + x * db;
}

Real SuperdiskEquations::axis_height() const {
    const Real q = exponent(), one = one_like(p);
    return pow_abs(one - exp(-(q * log(integer(2, p.precision())))), one / q);
}

Real SuperdiskEquations::a_priori_lower_bound(const Real& t) const {
    const mpfr_prec_t precision = p.precision();
    const Real q = exponent(), one = one_like(p), zero = integer(0, precision);
    const Real x = boundary_x(t), y1 = axis_height();
    // The upper bound of a >= 0: x/2, or x minus the root when (1 - 2^-q - (y1 - t x)^q) > 0.
    Real bound = x / integer(2, precision);
    const Real inside = one - exp(-(q * log(integer(2, precision)))) - pow_abs(y1 - t * x, q);
    if (positive(inside)) {
        const Real other = x - pow_abs(lower_point(inside), one / q);
        if (mpfr_cmp(other.hi(), bound.hi()) < 0) bound = other;
    }
    return lower_point(x * y1 - t * x * hull(zero, upper_point(bound)));
}

Real superdisk_area(const Real& p) {
    const Real one = one_like(p);
    const Real g = gamma(one + one / (2 * p));
    return 4 * (g * g) / gamma(one + one / p);
}

}  // namespace superpack_checker
