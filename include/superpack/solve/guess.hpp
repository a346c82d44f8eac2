// Plain floating-point scalars for *guesses* only: the generic formulas can be
// instantiated with double to find a starting box quickly; nothing computed here is ever
// reported or used as a verdict, and every guess is re-verified in interval arithmetic.
#pragma once
#include <cmath>

#include "superpack/arith/jet.hpp"

namespace superpack {

// Newton's method in double from `start`; returns the last iterate (no claim attached).
// Once a step is below 2^-26 of x, the next iterate is as good as double allows (Newton
// converges quadratically), so one more step is taken and the loop ends; waiting for a step
// of exactly zero can cycle between neighbouring doubles for all the iterations.
template <class F>
double guess_root(const F& f, double start, int iterations = 40) {
    double x = start;
    bool last = false;
    for (int k = 0; k < iterations; ++k) {
        const Jet<double> jet = f(variable(x));
        if (jet.derivative == 0 || !std::isfinite(jet.value)) break;
        const double next = x - jet.value / jet.derivative;
        if (next == x || last) return next > 0 ? next : x;
        last = std::fabs(next - x) <= std::ldexp(std::fabs(x), -26);
        x = next > 0 ? next : x / 2;
    }
    return x;
}

}  // namespace superpack
