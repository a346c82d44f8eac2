// Start-up self-test of directed rounding (as CAPD's DoubleRounding::test does).
// Hardware rounding can fail silently (compiler flags, a library resetting the FPU mode);
// no certificate may be written unless this passes.
#pragma once
#include <string>
#include <vector>

namespace superpack {

struct SelfTestReport {
    bool passed = true;
    std::vector<std::string> failures;  // one line per failed check
    int checks = 0;
};

// Checks, against exact rational (GMP) and MPFR references, that binary64 intervals
// enclose 1/3, 1 + 2^-60, sqrt(2), exp(1) and log(3) with lower < upper, and that Arb's
// balls contain the same references.
SelfTestReport run_rounding_self_test();

}  // namespace superpack
