// Start-up self-test of directed rounding (after CAPD's DoubleRounding::test).
// Hardware rounding can fail silently (compiler flags, a library resetting the FPU mode or
// setting flush-to-zero); no certificate may be written unless this passes.
#pragma once
#include <string>
#include <vector>

namespace superpack {

struct SelfTestReport {
    bool passed = true;
    std::vector<std::string> failures;  // one line per failed check: "name: reason"
    int checks = 0;
};

// Checks the rounding state before and after: round-to-nearest in the x87 control word
// (fegetround) and, on x86-64, in MXCSR, whose flush-to-zero and denormals-are-zero flags
// must be clear. Then, against exact rational (GMP) and MPFR references: binary64 intervals
// strictly enclose 1/3, 1 + 2^-60, 3 (1/3), 2^-1074 / 2 and 2^-1074 * 2^-1074 and give the exact
// points 2^-1022 * 3/4 and 3 2^-1074 - 2^-1074 (subnormals, which FTZ and DAZ break); both
// backends enclose sqrt(2), exp(1), log(3) and Gamma(5). Never throws: an exception inside a
// check is that check's failure.
SelfTestReport run_rounding_self_test();

}  // namespace superpack
