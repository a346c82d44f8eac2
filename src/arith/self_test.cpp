#include "superpack/arith/self_test.hpp"

#include <cfenv>

#include "superpack/arith/interval.hpp"

namespace superpack {

namespace {

// Does [lo, hi] (as exact MPFR values) hold the exact rational q, with lo < hi?
bool encloses_strictly(SelfTestReport& report, const std::string& name, const DInterval& x, const mpq_class& q) {
    ++report.checks;
    const bool ok = x.lower() < x.upper() && mpq_class(x.lower()) < q && q < mpq_class(x.upper());
    if (!ok) {
        report.passed = false;
        report.failures.push_back(name + ": binary64 interval does not strictly enclose the exact value");
    }
    return ok;
}

// Does [lo, hi] hold the MPFR value computed at 200 bits with directed rounding?
void encloses(SelfTestReport& report, const std::string& name, const DInterval& x, const Ball& y,
              int (*reference)(mpfr_t, const mpfr_t, mpfr_rnd_t), long argument) {
    ++report.checks;
    mpfr_t down, up, a;
    mpfr_inits2(200, down, up, a, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_si(a, argument, MPFR_RNDN);
    reference(down, a, MPFR_RNDD);
    reference(up, a, MPFR_RNDU);
    mpfr_t lo, hi;
    mpfr_inits2(300, lo, hi, static_cast<mpfr_ptr>(nullptr));
    get_bounds(lo, hi, x);
    bool ok = mpfr_cmp(lo, down) <= 0 && mpfr_cmp(up, hi) <= 0;
    get_bounds(lo, hi, y);
    ok = ok && mpfr_cmp(lo, down) <= 0 && mpfr_cmp(up, hi) <= 0;
    if (!ok) {
        report.passed = false;
        report.failures.push_back(name + ": enclosure misses the MPFR reference");
    }
    mpfr_clears(down, up, a, lo, hi, static_cast<mpfr_ptr>(nullptr));
}

}  // namespace

SelfTestReport run_rounding_self_test() {
    SelfTestReport report;
    ++report.checks;
    if (std::fegetround() != FE_TONEAREST) {
        report.passed = false;
        report.failures.push_back("FPU not in round-to-nearest at start-up");
    }
    const DoubleField d;
    const BallField b{128};
    // Division and addition must round apart: 1/3 and 1 + 2^-60 are not binary64 numbers.
    encloses_strictly(report, "1/3", d.integer(1) / d.integer(3), mpq_class(1, 3));
    const DInterval tiny = d.rational(mpq_class(1, mpz_class(1) << 60));
    encloses_strictly(report, "1 + 2^-60", d.integer(1) + tiny, mpq_class(1) + mpq_class(1, mpz_class(1) << 60));
    encloses_strictly(report, "3 * (1/3)", d.integer(3) * (d.integer(1) / d.integer(3)), mpq_class(1));
    encloses(report, "sqrt(2)", sqrt(d.integer(2)), sqrt(b.integer(2)), mpfr_sqrt, 2);
    encloses(report, "exp(1)", exp(d.integer(1)), exp(b.integer(1)), mpfr_exp, 1);
    encloses(report, "log(3)", log(d.integer(3)), log(b.integer(3)), mpfr_log, 3);
    encloses(report, "gamma(5)", gamma(d.integer(5)), gamma(b.integer(5)), mpfr_gamma, 5);
    ++report.checks;
    if (std::fegetround() != FE_TONEAREST) {
        report.passed = false;
        report.failures.push_back("rounding mode not restored after interval operations");
    }
    return report;
}

}  // namespace superpack
