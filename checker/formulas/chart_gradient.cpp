#include "checker/formulas/chart_gradient.hpp"

namespace superpack_checker {

namespace {

// The chain rule of a power: the kernel times x' in each coordinate x depends on.
Gradient chained(const Real& value, const Real& factor, const Gradient& x) {
    Gradient r{value, {}};
    for (int k = 0; k < chart_dimension; ++k)
        if (x.slope[k]) r.slope[k] = factor * *x.slope[k];
    return r;
}

bool depends(const Gradient& x) {
    for (const auto& s : x.slope)
        if (s) return true;
    return false;
}

}  // namespace

Real slope_at(const Gradient& g, int k) { return g.slope[k] ? *g.slope[k] : Real(g.value.precision()); }

Gradient constant(const Real& x) { return {x, {}}; }

Gradient variable(const Real& x, int k) {
    Gradient r{x, {}};
    r.slope[k] = integer(1, x.precision());
    return r;
}

Gradient operator+(const Gradient& a, const Gradient& b) {
    Gradient r{a.value + b.value, {}};
    for (int k = 0; k < chart_dimension; ++k) {
        if (a.slope[k] && b.slope[k]) r.slope[k] = *a.slope[k] + *b.slope[k];
        else if (a.slope[k]) r.slope[k] = a.slope[k];
        else if (b.slope[k]) r.slope[k] = b.slope[k];
    }
    return r;
}

Gradient operator-(const Gradient& a, const Gradient& b) {
    Gradient r{a.value - b.value, {}};
    for (int k = 0; k < chart_dimension; ++k) {
        if (a.slope[k] && b.slope[k]) r.slope[k] = *a.slope[k] - *b.slope[k];
        else if (a.slope[k]) r.slope[k] = a.slope[k];
        else if (b.slope[k]) r.slope[k] = -*b.slope[k];
    }
    return r;
}

Gradient operator-(const Gradient& a) {
    Gradient r{-a.value, {}};
    for (int k = 0; k < chart_dimension; ++k)
        if (a.slope[k]) r.slope[k] = -*a.slope[k];
    return r;
}

Gradient operator*(const Gradient& a, const Gradient& b) {
    Gradient r{a.value * b.value, {}};
    for (int k = 0; k < chart_dimension; ++k) {
        if (a.slope[k] && b.slope[k]) r.slope[k] = *a.slope[k] * b.value + a.value * *b.slope[k];
        else if (a.slope[k]) r.slope[k] = *a.slope[k] * b.value;
        else if (b.slope[k]) r.slope[k] = a.value * *b.slope[k];
    }
    return r;
}

Gradient operator/(const Gradient& a, const Gradient& b) {
    const Real quotient = a.value / b.value;
    Gradient r{quotient, {}};
    for (int k = 0; k < chart_dimension; ++k) {
        if (a.slope[k] && b.slope[k]) r.slope[k] = (*a.slope[k] - quotient * *b.slope[k]) / b.value;
        else if (a.slope[k]) r.slope[k] = *a.slope[k] / b.value;
        else if (b.slope[k]) r.slope[k] = -(quotient * *b.slope[k]) / b.value;
    }
    return r;
}

Gradient operator*(const Real& c, const Gradient& a) {
    Gradient r{c * a.value, {}};
    for (int k = 0; k < chart_dimension; ++k)
        if (a.slope[k]) r.slope[k] = c * *a.slope[k];
    return r;
}

Gradient operator*(const Gradient& a, const Real& c) {
    Gradient r{a.value * c, {}};
    for (int k = 0; k < chart_dimension; ++k)
        if (a.slope[k]) r.slope[k] = *a.slope[k] * c;
    return r;
}

Gradient chart_pow_abs(const Gradient& x, const Exponent& y) {
    if (!depends(x)) return constant(chart_pow_abs(x.value, y));
    const PowerPair power = chart_pow_abs_pair(x.value, y);
    return chained(power.value, y.y * power.kernel, x);
}

Gradient chart_pow_positive(const Gradient& x, const Exponent& y) {
    if (!depends(x)) return constant(chart_pow_positive(x.value, y));
    const PowerPair power = chart_pow_positive_pair(x.value, y);
    return chained(power.value, y.y * power.kernel, x);
}

}  // namespace superpack_checker
