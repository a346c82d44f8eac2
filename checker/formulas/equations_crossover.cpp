#include "checker/formulas/equations_crossover.hpp"

#include <stdexcept>

namespace superpack_checker {

namespace {
Real one_like(const Real& x) { return integer(1, x.precision()); }
Real ln2(mpfr_prec_t precision) { return log(integer(2, precision)); }
}  // namespace

Real digamma(const Real& x) {
    if (!positive(x)) throw std::domain_error("digamma of an interval that may be <= 0");
    Real result(x.precision());
    mpfr_digamma(result.lower_end(), x.lo(), MPFR_RNDD);
    mpfr_digamma(result.upper_end(), x.hi(), MPFR_RNDU);
    return result;
}

ValueAndSlope halving_shift(const Real& p) {
    const Real t = CubicEquation{false, p}.shift();
    return {t, t * ln2(p.precision()) / (2 * (p * p))};
}

ValueAndSlope superball_volume_with_slope(const Real& p) {
    const Real volume = superball_volume(p), one = one_like(p);
    const Real inverse = one / (2 * p);
    const Real log_slope = (-3 * one) / (2 * (p * p)) * (digamma(one + inverse) - digamma(one + 3 * inverse));
    return {volume, volume * log_slope};
}

ValueAndSlope octahedral_height_with_slope(const Real& p) {
    const Real one = one_like(p), e = 2 * p;
    const Real power = exp((one - e) * ln2(p.precision()));  // 2^(1-2p)
    const Real u = one - power;
    const Real c = o0_height(p);
    const Real u_slope = 2 * (ln2(p.precision()) * power);
    return {c, c * (u_slope / (e * u) - log(u) / (2 * (p * p)))};
}

Real cubic_slope_in_s(const CubicEquation& equation, const Real& s) {
    if (mpfr_sgn(s.lo()) < 0) throw std::domain_error("cubic_slope_in_s: s may be negative");
    const Real e = 2 * equation.p, e1 = e - one_like(s);
    return e * (pow_abs(s + equation.shift(), e1) + (equation.c1 ? 2 : 1) * pow_abs(s, e1));
}

Real cubic_slope_in_p(const CubicEquation& equation, const Real& s) {
    const Real& p = equation.p;
    const Real e = 2 * p;
    const ValueAndSlope t = halving_shift(p);
    const Real u = s + t.value;
    const Real shifted = pow_abs(u, e) * (2 * log(u) + e * t.slope / u);
    const Real plain = pow_abs(s, e) * (2 * log(s));
    if (equation.c1) return shifted + 2 * plain;
    const Real l2 = ln2(p.precision());
    return shifted + plain - 2 * (l2 * exp(-e * l2));
}

ValueAndSlope cubic_root_with_slope(const CubicEquation& equation, const Real& s) {
    return {s, -(cubic_slope_in_p(equation, s) / cubic_slope_in_s(equation, s))};
}

ValueAndSlope cubic_abs_determinant(bool c1, const ValueAndSlope& s, const ValueAndSlope& t) {
    if (!c1) {
        const Real inner = 2 * s.value + t.value;
        return {8 * (t.value * inner), 8 * (t.slope * inner + t.value * (2 * s.slope + t.slope))};
    }
    const Real inner = 3 * s.value + t.value, square = t.value * t.value;
    return {8 * (square * inner), 16 * (t.value * t.slope * inner) + 8 * (square * (3 * s.slope + t.slope))};
}

ValueAndSlope octahedral_abs_determinant(const ValueAndSlope& c) { return {8 * c.value, 8 * c.slope}; }

std::string determinant_identity_failure(mpfr_prec_t precision) {
    auto same = [](const Real& a, const Real& b) { return subset(a, b) && subset(b, a); };
    for (long i = 0; i <= 3; ++i) {
        const Real x = integer(i, precision);
        if (!same(determinant(o0_basis(x)), 8 * x)) return "O0 at c = " + std::to_string(i);
        for (long j = 0; j <= 3; ++j) {
            const Real s = x, t = integer(j, precision);
            const std::string at = " at (s, t) = (" + std::to_string(i) + ", " + std::to_string(j) + ")";
            if (!same(determinant(c0_basis(s, t)), -(8 * (t * (2 * s + t))))) return "C0" + at;
            if (!same(determinant(c1_basis(s, t)), 8 * (t * t * (3 * s + t)))) return "C1" + at;
        }
    }
    return "";
}

ValueAndSlope density_with_slope(const ValueAndSlope& volume, const ValueAndSlope& abs_determinant) {
    const Real& d = abs_determinant.value;
    return {volume.value / d, (volume.slope * d - volume.value * abs_determinant.slope) / (d * d)};
}

ValueAndSlope cubic_crossover_function(const ValueAndSlope& s0, const ValueAndSlope& s1, const ValueAndSlope& t) {
    const Real value = 2 * s0.value + t.value - 3 * (t.value * s1.value) - t.value * t.value;
    const Real slope =
        2 * s0.slope + t.slope - 3 * (t.slope * s1.value + t.value * s1.slope) - 2 * (t.value * t.slope);
    return {value, slope};
}

Surd operator+(const Surd& x, const Surd& y) { return {x.a + y.a, x.b + y.b}; }
Surd operator-(const Surd& x, const Surd& y) { return {x.a - y.a, x.b - y.b}; }
Surd operator*(const Surd& x, const Surd& y) { return {x.a * y.a + 2 * x.b * y.b, x.a * y.b + x.b * y.a}; }
bool operator==(const Surd& x, const Surd& y) { return x.a == y.a && x.b == y.b; }

// a + b sqrt2: when a and b differ in sign, the larger of a^2 and 2b^2 wins (never equal
// unless both vanish, as sqrt2 is irrational).
int sign(const Surd& x) {
    const int sa = sgn(x.a), sb = sgn(x.b);
    if (sa == 0 || sa == sb) return sb == 0 ? sa : sb;
    if (sb == 0) return sa;
    return x.a * x.a > 2 * x.b * x.b ? sa : sb;
}

Surd sphere_point_shift() { return {0, mpq_class(1, 2)}; }

Surd sphere_point_cubic_equation(bool c1, const Surd& s) {
    const Surd shifted = s + sphere_point_shift();
    const Surd square = shifted * shifted, plain = s * s;
    if (c1) return square + plain + plain - Surd{1, 0};
    return square + plain + Surd{mpq_class(1, 4), 0} - Surd{1, 0};
}

Surd sphere_point_crossover_function(const Surd& s0, const Surd& s1) {
    const Surd t = sphere_point_shift();
    return s0 + s0 + t - Surd{3, 0} * t * s1 - t * t;
}

}  // namespace superpack_checker
