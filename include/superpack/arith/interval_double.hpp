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

// Directed roundings from the round-to-nearest result and the sign of its exact error, with no
// change of the rounding mode (MXCSR writes were a fifth of the time of a density; the
// start-up self-test checks that the mode is round-to-nearest). NOTES.md section 1.1 proves
// when the error found by TwoSum or one fused multiply-add has the right sign: for a sum unless
// an operation overflows, for a product p when |p| >= 2^-968, for a quotient when
// |x| >= 2^-968 and x / y rounds to a normal number, for a square root when x >= 2^-968.
// Outside those ranges (tiny operands or results, overflow, infinite operands) the `*_edge`
// functions find the sign from the operands scaled to [1/2, 1), which is slower and rare.
// So every result is the exact rounding down or up of the exact value: exact results stay
// exact (2 * (1/2) = 1, [0, b] * [0, c] >= 0, 0 stays 0) and the others get two neighbours.
struct rounded_arith_outward {
    void init() {}
    template <class U> double conv_down(const U& v) { return convert(v, false); }
    template <class U> double conv_up(const U& v) { return convert(v, true); }
    double add_down(double x, double y) { return sum(x, y, false); }
    double sub_down(double x, double y) { return sum(x, -y, false); }
    double add_up(double x, double y) { return sum(x, y, true); }
    double sub_up(double x, double y) { return sum(x, -y, true); }
    double mul_down(double x, double y) { return product(x, y, false); }
    double mul_up(double x, double y) { return product(x, y, true); }
    double div_down(double x, double y) { return quotient(x, y, false); }
    double div_up(double x, double y) { return quotient(x, y, true); }
    // Any number between x and y will do: Boost uses it for midpoints (guesses).
    double median(double x, double y) {
        const double m = x / 2 + y / 2;
        return m < x ? x : (m > y ? y : m);
    }
    double sqrt_down(double x) { return root(x, false); }
    double sqrt_up(double x) { return root(x, true); }
    double int_down(double x) { return std::floor(x); }
    double int_up(double x) { return std::ceil(x); }

private:
    static constexpr double kLargest = std::numeric_limits<double>::max();
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    static constexpr double kSmallestNormal = std::numeric_limits<double>::min();
    static constexpr double kResidualFloor = 0x1p-968;  // NOTES.md 1.1, the residual lemma

    // r rounded to nearest, stepped in the direction of the exact value if it lies there.
    static double step(double r, double error, bool upward) {
        if (upward) return error > 0 ? next_up(r) : r;
        return error < 0 ? next_down(r) : r;
    }
    // The whole line: the bound for an undefined value (a NaN from 0 * inf, inf - inf, 0 / 0).
    static double unbounded(bool upward) { return upward ? kInfinity : -kInfinity; }
    // r is +-inf from finite operands: the exact value lies beyond the largest double.
    static double overflowed(double r, bool upward) {
        if (upward) return r > 0 ? kInfinity : -kLargest;
        return r > 0 ? kLargest : -kInfinity;
    }
    static bool finite(double x) { return std::fabs(x) <= kLargest; }

    // x + y - s by Knuth's TwoSum: exact unless one of its six operations overflows, and then
    // the error is not finite (an infinity cannot cancel back to a finite number).
    static double sum(double x, double y, bool upward) {
        const double s = x + y;
        const double y_part = s - x;
        const double x_part = s - y_part;
        const double error = (x - x_part) + (y - y_part);
        return finite(error) ? step(s, error, upward) : sum_edge(x, y, s, upward);
    }
    static double sum_edge(double x, double y, double s, bool upward) {
        if (!finite(x) || !finite(y)) return s == s ? s : unbounded(upward);  // inf + finite is exact
        if (!finite(s)) return overflowed(s, upward);
        // s is finite and TwoSum overflowed inside (e.g. 3 2^970 - DBL_MAX): Dekker's Fast2Sum,
        // larger operand first, is exact and its s - large is exact, so it cannot overflow.
        const bool x_larger = std::fabs(x) >= std::fabs(y);
        const double large = x_larger ? x : y, small = x_larger ? y : x;
        return step(s, small - (s - large), upward);
    }

    // x y - p by one FMA: exact when |p| >= 2^-968, because then ulp(x) ulp(y) >= 2^-1074.
    static double product(double x, double y, bool upward) {
        const double p = x * y;
        if (std::fabs(p) >= kResidualFloor && std::fabs(p) <= kLargest) return step(p, std::fma(x, y, -p), upward);
        return product_edge(x, y, p, upward);
    }
    static double product_edge(double x, double y, double p, bool upward) {
        if (x == 0 || y == 0) return 0.0;  // exact, also against an infinite end
        if (!finite(x) || !finite(y)) return p == p ? p : unbounded(upward);
        if (!finite(p)) return overflowed(p, upward);
        // |p| < 2^-968: x = mx 2^ex, y = my 2^ey with |mx|, |my| in [1/2, 1), and
        // mx my - p 2^-(ex+ey) = 2^-(ex+ey) (x y - p) is a nonzero multiple of 2^-106 or 0.
        int ex = 0, ey = 0;
        const double mx = std::frexp(x, &ex), my = std::frexp(y, &ey);
        return step(p == 0 ? 0.0 : p, std::fma(mx, my, -std::ldexp(p, -(ex + ey))), upward);
    }

    // x - q y by one FMA, whose sign times that of y is the sign of x / y - q: exact when
    // |x| >= 2^-968 and q is normal, because then ulp(q) ulp(y) >= 2^-1074.
    static double quotient(double x, double y, bool upward) {
        const double q = x / y;
        if (std::fabs(x) >= kResidualFloor && std::fabs(q) >= kSmallestNormal && std::fabs(q) <= kLargest) {
            const double remainder = std::fma(-q, y, x);
            return step(q, y > 0 ? remainder : -remainder, upward);
        }
        return quotient_edge(x, y, q, upward);
    }
    static double quotient_edge(double x, double y, double q, bool upward) {
        if (q != q || y == 0) return unbounded(upward);  // 0 / 0, inf / inf, x / 0
        if (x == 0) return 0.0;
        if (!finite(x) || !finite(y)) return q == 0 ? 0.0 : q;  // inf / finite, finite / inf: exact
        if (!finite(q)) return overflowed(q, upward);
        // x = mx 2^ex, y = my 2^ey: mx - (q 2^(ey-ex)) my = 2^-ex (x - q y), a nonzero multiple
        // of 2^-107 or 0.
        int ex = 0, ey = 0;
        const double mx = std::frexp(x, &ex), my = std::frexp(y, &ey);
        const double remainder = std::fma(-std::ldexp(q, ey - ex), my, mx);
        return step(q == 0 ? 0.0 : q, y > 0 ? remainder : -remainder, upward);
    }

    // x - r r by one FMA, with the sign of sqrt(x) - r: exact when x >= 2^-968, because then
    // ulp(r)^2 >= 2^-1072.
    static double root(double x, bool upward) {
        const double r = std::sqrt(x);
        if (x >= kResidualFloor && x <= kLargest) return step(r, std::fma(-r, r, x), upward);
        return root_edge(x, r, upward);
    }
    static double root_edge(double x, double r, bool upward) {
        if (x != x) return unbounded(upward);
        if (x <= 0) return 0.0;  // Boost asks only for x > 0; sqrt of [a <= 0, b] starts at 0
        if (!finite(x)) return r;
        // x = m 2^e with e even and m in [1/2, 2): m - (r 2^(-e/2))^2 = 2^-e (x - r r), a
        // nonzero multiple of 2^-106 or 0.
        int e = 0;
        double m = std::frexp(x, &e);
        if (e % 2 != 0) {
            m *= 2;
            --e;
        }
        const double scaled = std::ldexp(r, -e / 2);
        return step(r, std::fma(-scaled, scaled, m), upward);
    }

    template <class U> static double convert(const U& v, bool upward) {
        const double d = static_cast<double>(v);
        if constexpr (std::is_floating_point_v<U> && sizeof(U) <= sizeof(double)) {
            return d;  // exact
        } else {
            if (static_cast<U>(d) == v) return d;
            return upward ? next_up(d) : next_down(d);
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
