// Binary64 intervals: Boost.Interval whose directed roundings are made from the
// round-to-nearest result and the sign of its exact error, and whose exp, log and Gamma come from
// superpack's own series with proved remainders (elementary_double.hpp), never from libm.
#pragma once
#include <boost/numeric/interval.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace superpack {

namespace detail {

// The binary64 neighbours of x.
inline double next_up(double x) {
    if (!(x < std::numeric_limits<double>::infinity())) return x;  // +inf, NaN
    if (x == 0) return std::numeric_limits<double>::denorm_min();
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits = x > 0 ? bits + 1 : bits - 1;
    std::memcpy(&x, &bits, sizeof bits);
    return x;
}
inline double next_down(double x) { return -next_up(-x); }

// Directed roundings from the round-to-nearest result and the sign of its error, with no
// change of the rounding mode (MXCSR writes were a fifth of the time of a density; the
// start-up self-test checks that the mode is round-to-nearest). The error of + and - is
// exact by TwoSum; the error of *, / and sqrt is exact by one fused multiply-add. Below
// 2^-960 an error may underflow, so there a result is stepped outward without looking.
// Exact results stay exact: [0, b] * [0, c] stays non-negative and 2 * (1/2) is 1.
struct rounded_arith_outward {
    void init() {}
    template <class U> double conv_down(const U& v) { return convert(v, false); }
    template <class U> double conv_up(const U& v) { return convert(v, true); }
    double add_down(double x, double y) { const double s = x + y; return down(s, sum_error(x, y, s), true); }
    double sub_down(double x, double y) { const double s = x - y; return down(s, sum_error(x, -y, s), true); }
    double add_up(double x, double y) { const double s = x + y; return up(s, sum_error(x, y, s), true); }
    double sub_up(double x, double y) { const double s = x - y; return up(s, sum_error(x, -y, s), true); }
    double mul_down(double x, double y) { const double p = x * y; return down(p, std::fma(x, y, -p), x == 0 || y == 0); }
    double mul_up(double x, double y) { const double p = x * y; return up(p, std::fma(x, y, -p), x == 0 || y == 0); }
    double div_down(double x, double y) { const double q = x / y; return down(q, quotient_error(x, y, q), x == 0); }
    double div_up(double x, double y) { const double q = x / y; return up(q, quotient_error(x, y, q), x == 0); }
    // Any number between x and y will do: Boost uses it for midpoints (guesses).
    double median(double x, double y) {
        const double m = x / 2 + y / 2;
        return m < x ? x : (m > y ? y : m);
    }
    double sqrt_down(double x) { const double r = std::sqrt(x); return x <= 0 ? 0.0 : down(r, std::fma(-r, r, x), false); }
    double sqrt_up(double x) { const double r = std::sqrt(x); return x <= 0 ? 0.0 : up(r, std::fma(-r, r, x), false); }
    double int_down(double x) { return std::floor(x); }
    double int_up(double x) { return std::ceil(x); }

private:
    static constexpr double kErrorFloor = 0x1p-960;
    // x + y - s exactly (Knuth's TwoSum, round-to-nearest).
    static double sum_error(double x, double y, double s) {
        const double y_part = s - x;
        const double x_part = s - y_part;
        return (x - x_part) + (y - y_part);
    }
    // The sign of x / y - q is that of (x - q y) / y.
    static double quotient_error(double x, double y, double q) {
        const double remainder = std::fma(-q, y, x);
        return y > 0 ? remainder : -remainder;
    }
    // `error` has the sign of (exact result) - r wherever |r| >= kErrorFloor; `zero_exact` says
    // that a zero r is exact (a sum, or a product with a zero operand).
    static bool tiny_or_infinite(double r) {
        return !(std::fabs(r) >= kErrorFloor && std::fabs(r) < std::numeric_limits<double>::infinity());
    }
    static double down(double r, double error, bool zero_exact) {
        if (tiny_or_infinite(r)) return r == 0 && zero_exact ? 0.0 : next_down(r);
        return error < 0 ? next_down(r) : r;
    }
    static double up(double r, double error, bool zero_exact) {
        if (tiny_or_infinite(r)) return r == 0 && zero_exact ? 0.0 : next_up(r);
        return error > 0 ? next_up(r) : r;
    }
    template <class U> static double convert(const U& v, bool up) {
        const double d = static_cast<double>(v);
        if constexpr (std::is_floating_point_v<U> && sizeof(U) <= sizeof(double)) {
            return d;  // exact
        } else {
            if (static_cast<U>(d) == v) return d;
            return up ? next_up(d) : next_down(d);
        }
    }
};

}  // namespace detail

// No transcendental member: boost::numeric::exp and friends do not compile for DInterval,
// so the only exp, log and Gamma are superpack's rigorous ones (interval.hpp).
using DoublePolicies = boost::numeric::interval_lib::policies<
    boost::numeric::interval_lib::save_state_nothing<detail::rounded_arith_outward>,
    boost::numeric::interval_lib::checking_strict<double>>;

using DInterval = boost::numeric::interval<double, DoublePolicies>;

}  // namespace superpack
