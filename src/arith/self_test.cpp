#include "superpack/arith/mpfr_bounds.hpp"
#include "superpack/arith/self_test.hpp"

#include <cfenv>
#include <exception>
#include <functional>
#include <limits>

#include "superpack/arith/interval.hpp"

#if defined(__x86_64__) || defined(__SSE2__)
#include <xmmintrin.h>
#define SUPERPACK_HAVE_MXCSR 1
#endif

namespace superpack {

namespace {

// One check: `body` returns an empty string when it passes and the reason otherwise. An
// exception inside it is that check's failure, with its message, so the report lists every
// failed check and the self-test itself never throws.
void check(SelfTestReport& report, const std::string& name, const std::function<std::string()>& body) {
    ++report.checks;
    std::string reason;
    try {
        reason = body();
    } catch (const std::exception& error) {
        reason = std::string("exception: ") + error.what();
    } catch (...) {
        reason = "unknown exception";
    }
    if (!reason.empty()) {
        report.passed = false;
        report.failures.push_back(name + ": " + reason);
    }
}

// Does [lo, hi] hold the exact rational q strictly (or, for an exact point, is it that point)?
std::string encloses_strictly(const DInterval& x, const mpq_class& q) {
    const bool ok = x.lower() < x.upper() && mpq_class(x.lower()) < q && q < mpq_class(x.upper());
    return ok ? "" : "binary64 interval does not strictly enclose the exact value";
}
std::string is_point(const DInterval& x, const mpq_class& q) {
    const bool ok = x.lower() == x.upper() && mpq_class(x.lower()) == q;
    return ok ? "" : "binary64 interval of an exact result is not that point";
}

// Does [lo, hi] hold the MPFR value computed at 200 bits with directed rounding?
std::string encloses(const DInterval& x, const Ball& y, int (*reference)(mpfr_t, const mpfr_t, mpfr_rnd_t),
                     long argument) {
    mpfr_t down, up, a, lo, hi;
    mpfr_inits2(200, down, up, a, static_cast<mpfr_ptr>(nullptr));
    mpfr_inits2(300, lo, hi, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_si(a, argument, MPFR_RNDN);
    reference(down, a, MPFR_RNDD);
    reference(up, a, MPFR_RNDU);
    get_bounds(lo, hi, x);
    const bool binary64 = mpfr_cmp(lo, down) <= 0 && mpfr_cmp(up, hi) <= 0;
    get_bounds(lo, hi, y);
    const bool arb = mpfr_cmp(lo, down) <= 0 && mpfr_cmp(up, hi) <= 0;
    mpfr_clears(down, up, a, lo, hi, static_cast<mpfr_ptr>(nullptr));
    if (!binary64) return "binary64 enclosure misses the MPFR reference";
    return arb ? "" : "Arb enclosure misses the MPFR reference";
}

// The rounding state every binary64 interval operation relies on (NOTES.md 1.1): round to
// nearest in the x87 control word (what glibc's fegetround reads on x86-64) and in MXCSR
// (what SSE arithmetic uses), and no flush-to-zero or denormals-are-zero, which would break
// the subnormal cases of the directed roundings.
void check_rounding_state(SelfTestReport& report, const std::string& when) {
    check(report, "x87 rounding mode " + when, [] {
        return std::fegetround() == FE_TONEAREST ? "" : "fegetround() is not FE_TONEAREST";
    });
#ifdef SUPERPACK_HAVE_MXCSR
    const unsigned mxcsr = _mm_getcsr();
    check(report, "MXCSR rounding control " + when, [mxcsr] {
        return (mxcsr & 0x6000u) == 0 ? "" : "MXCSR rounding control is not round-to-nearest";
    });
    check(report, "MXCSR flush-to-zero " + when, [mxcsr] {
        return (mxcsr & 0x8000u) == 0 ? "" : "MXCSR flush-to-zero (FTZ, bit 15) is set";
    });
    check(report, "MXCSR denormals-are-zero " + when, [mxcsr] {
        return (mxcsr & 0x0040u) == 0 ? "" : "MXCSR denormals-are-zero (DAZ, bit 6) is set";
    });
#endif
}

mpq_class power_of_two(int exponent) {
    const mpz_class power = mpz_class(1) << (exponent < 0 ? -exponent : exponent);
    return exponent < 0 ? mpq_class(mpz_class(1), power) : mpq_class(power);
}

}  // namespace

SelfTestReport run_rounding_self_test() {
    SelfTestReport report;
    check_rounding_state(report, "at start-up");
    const DoubleField d;
    const BallField b{128};
    // Division and addition must round apart: 1/3 and 1 + 2^-60 are not binary64 numbers.
    check(report, "1/3", [&] { return encloses_strictly(d.integer(1) / d.integer(3), mpq_class(1, 3)); });
    check(report, "1 + 2^-60", [&] {
        return encloses_strictly(d.integer(1) + d.rational(power_of_two(-60)), 1 + power_of_two(-60));
    });
    check(report, "3 * (1/3)", [&] { return encloses_strictly(d.integer(3) * (d.integer(1) / d.integer(3)), 1); });
    // Subnormals, where flush-to-zero and denormals-are-zero change results: a quotient and a
    // product below 2^-1074 lie strictly between 0 and 2^-1074, and a subnormal product and a
    // sum of subnormals are exact points.
    const DInterval smallest(std::numeric_limits<double>::denorm_min());
    check(report, "2^-1074 / 2", [&] { return encloses_strictly(smallest / d.integer(2), power_of_two(-1075)); });
    check(report, "2^-1074 * 2^-1074", [&] { return encloses_strictly(smallest * smallest, power_of_two(-2148)); });
    check(report, "2^-1022 * 3/4", [&] {
        return is_point(DInterval(0x1p-1022) * d.rational(mpq_class(3, 4)), 3 * power_of_two(-1024));
    });
    check(report, "3 2^-1074 - 2^-1074", [&] { return is_point(smallest * d.integer(3) - smallest, power_of_two(-1073)); });
    check(report, "sqrt(2)", [&] { return encloses(sqrt(d.integer(2)), sqrt(b.integer(2)), mpfr_sqrt, 2); });
    check(report, "exp(1)", [&] { return encloses(exp(d.integer(1)), exp(b.integer(1)), mpfr_exp, 1); });
    check(report, "log(3)", [&] { return encloses(log(d.integer(3)), log(b.integer(3)), mpfr_log, 3); });
    check(report, "gamma(5)", [&] { return encloses(gamma(d.integer(5)), gamma(b.integer(5)), mpfr_gamma, 5); });
    check_rounding_state(report, "after interval operations");
    return report;
}

}  // namespace superpack
