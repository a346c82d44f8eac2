#include "superpack/problems/difference_gauge.hpp"

#include <algorithm>
#include <cmath>

namespace superpack {

namespace {

// The least c >= max(a, b) with (c - a)^r + (c - b)^r >= w, r = 1/q > 1: the left side is convex
// and increasing in c, so Newton's method from a point above the root descends to it monotonically.
double level(double a, double b, double w, double r) {
    const double low = std::max(a, b);
    auto h = [&](double c) { return std::pow(c - a, r) + std::pow(c - b, r) - w; };
    if (h(low) >= 0) return low;
    double c = low + std::pow(w, 1 / r);  // one term alone reaches w there
    for (int step = 0; step < 60; ++step) {
        const double value = h(c);
        const double slope = r * (std::pow(c - a, r - 1) + std::pow(c - b, r - 1));
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
