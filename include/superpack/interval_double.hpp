// Binary64 intervals: Boost.Interval with hardware directed rounding for + - * / sqrt, and
// transcendental bounds taken from Arb, because Boost's libm-backed transcendental policy trusts glibc's
// libm to honour the rounding mode, which it does not.
#pragma once
#include <boost/numeric/interval.hpp>
#include <cmath>
#include <xmmintrin.h>

namespace superpack {

namespace detail {

// Outward-rounded exp and log of one double, computed by Arb at 64 bits and rounded to
// the enclosing binary64 endpoint. The FPU mode is set to nearest around the call because
// Arb's own double heuristics assume it.
double arb_exp_down(double x);
double arb_exp_up(double x);
double arb_log_down(double x);
double arb_log_up(double x);

// Hides a value from the optimiser: the compiler must assume it changes here, so an
// operation on it cannot be merged with the same operation under another rounding mode.
// GCC's -frounding-math does not stop such merging (the self-test caught 1/3 computed once
// for both bounds), so every directed operation goes through this barrier.
inline double opaque(double x) {
    asm volatile("" : "+x"(x));
    return x;
}

// Rounding control through the SSE control register MXCSR, which alone governs binary64
// arithmetic on x86-64. Boost's c99 control calls glibc's fesetround, which also rewrites the
// x87 control word and took a third of the time of a density computation.
struct sse_rounding_control {
    using rounding_mode = unsigned int;
    static constexpr unsigned int mask = 0x6000, nearest = 0x0000, down = 0x2000, up = 0x4000, zero = 0x6000;
    static void set(unsigned int mode) { _mm_setcsr((_mm_getcsr() & ~mask) | mode); }
    static void get_rounding_mode(rounding_mode& mode) { mode = _mm_getcsr() & mask; }
    static void set_rounding_mode(rounding_mode mode) { set(mode); }
    static void downward() { set(down); }
    static void upward() { set(up); }
    static void to_nearest() { set(nearest); }
    static void toward_zero() { set(zero); }
    static double to_int(double x) { return std::nearbyint(x); }
    static double force_rounding(double x) { return x; }
};

// Boost's rounded_arith_std with an optimisation barrier around each directed operation.
struct rounded_arith_opaque : sse_rounding_control {
    void init() {}
    template <class U> double conv_down(const U& v) { this->downward(); return opaque(static_cast<double>(v)); }
    template <class U> double conv_up(const U& v) { this->upward(); return opaque(static_cast<double>(v)); }
    double add_down(double x, double y) { this->downward(); return opaque(opaque(x) + opaque(y)); }
    double sub_down(double x, double y) { this->downward(); return opaque(opaque(x) - opaque(y)); }
    double mul_down(double x, double y) { this->downward(); return opaque(opaque(x) * opaque(y)); }
    double div_down(double x, double y) { this->downward(); return opaque(opaque(x) / opaque(y)); }
    double add_up(double x, double y) { this->upward(); return opaque(opaque(x) + opaque(y)); }
    double sub_up(double x, double y) { this->upward(); return opaque(opaque(x) - opaque(y)); }
    double mul_up(double x, double y) { this->upward(); return opaque(opaque(x) * opaque(y)); }
    double div_up(double x, double y) { this->upward(); return opaque(opaque(x) / opaque(y)); }
    double median(double x, double y) { this->to_nearest(); return opaque((opaque(x) + opaque(y)) / 2); }
    double sqrt_down(double x) { this->downward(); return opaque(std::sqrt(opaque(x))); }
    double sqrt_up(double x) { this->upward(); return opaque(std::sqrt(opaque(x))); }
    double int_down(double x) { this->downward(); return this->to_int(opaque(x)); }
    double int_up(double x) { this->upward(); return this->to_int(opaque(x)); }
};

template <class T>
struct rounded_transc_arb;

template <>
struct rounded_transc_arb<double> : rounded_arith_opaque {
    double exp_down(double x) { return arb_exp_down(x); }
    double exp_up(double x) { return arb_exp_up(x); }
    double log_down(double x) { return arb_log_down(x); }
    double log_up(double x) { return arb_log_up(x); }
};

}  // namespace detail

using DoublePolicies = boost::numeric::interval_lib::policies<
    boost::numeric::interval_lib::save_state<detail::rounded_transc_arb<double>>,
    boost::numeric::interval_lib::checking_strict<double>>;

// The double-precision interval type. Only exp, log, sqrt and integer powers are available
// as transcendental operations; anything else fails to compile rather than using libm.
using DInterval = boost::numeric::interval<double, DoublePolicies>;

}  // namespace superpack
