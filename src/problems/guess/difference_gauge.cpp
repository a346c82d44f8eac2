#include "superpack/problems/guess/difference_gauge.hpp"

#include <algorithm>
#include <cmath>

namespace superpack {

namespace {

// The least c >= max(a, b) with (c - a)^r + (c - b)^r >= w, r = 1/q > 1: the left side is convex
// and increasing in c, so Newton's method from a point above the root descends to it monotonically.
// The start: with d = c - max(a, b) and e = |a - b| the equation is d^r + (d + e)^r = w, so
// d <= w^(1/r) - e, and there the left side is already >= w. Starting that close matters: far
// above the root each Newton step only shrinks the distance by 1 - 1/r (0.8 at p = 1/10), and this
// function is the search's inner loop at small p.
double level(double a, double b, double w, double r) {
    const double low = std::max(a, b);
    const double gap = std::fabs(a - b);
    if (std::pow(gap, r) >= w) return low;
    double c = low + std::max(0.0, std::pow(w, 1 / r) - gap);
    for (int step = 0; step < 60; ++step) {
        const double s = c - a, t = c - b;
        const double power_s = std::pow(s, r), power_t = std::pow(t, r);
        const double value = power_s + power_t - w;
        // d/dc (c - a)^r = r (c - a)^r / (c - a), and 0 at c = a since r > 1.
        const double slope = r * ((s > 0 ? power_s / s : 0) + (t > 0 ? power_t / t : 0));
        if (!(value > 0) || !(slope > 0)) break;
        const double next = std::max(low, c - value / slope);
        if (!(next < c)) break;
        c = next;
    }
    return c;
}

}  // namespace

double difference_gauge(const std::array<double, 3>& v, double p) {
    const double largest = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
    if (largest == 0) return 0;
    const double q = 2 * p;
    std::array<double, 3> w{}, powers{};
    for (int i = 0; i < 3; ++i) {
        w[i] = std::fabs(v[i]) / largest;
        powers[i] = std::pow(w[i], q);
    }
    if (q >= 1) {  // D = 2K: half the 2p-norm
        const double sum = powers[0] + powers[1] + powers[2];
        return largest * std::pow(sum, 1 / q) / 2;
    }
    double least = HUGE_VAL;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (int split = 0; split < 4; ++split) {
            // Bit 0: x_i = v_i (its power counts in g(x)), else x_i = 0 (in g(x - v)); bit 1 for j.
            const double a = (split & 1 ? powers[i] : 0) + (split & 2 ? powers[j] : 0);
            const double b = powers[i] + powers[j] - a;
            if (std::max(a, b) >= least) continue;
            least = std::min(least, level(a, b, w[k], 1 / q));
        }
    }
    return largest * std::pow(least, 1 / q);
}

}  // namespace superpack
