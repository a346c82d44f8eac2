// The start-up rounding self-test must notice a wrong rounding state that glibc's fegetround
// does not see on x86-64 (it reads only the x87 control word): MXCSR set to round down or
// toward zero, flush-to-zero or denormals-are-zero. Each must make it fail, with a failure
// that names the flag, and it must pass again once MXCSR is restored.
#include <string>

#include "superpack/arith/self_test.hpp"
#include "support.hpp"

#if defined(__x86_64__) || defined(__SSE2__)
#include <xmmintrin.h>

using namespace superpack;

namespace {

// Sets MXCSR for its lifetime and restores it afterwards, also when something throws.
class MxcsrOverride {
public:
    MxcsrOverride(unsigned set, unsigned clear) : saved_(_mm_getcsr()) { _mm_setcsr((saved_ & ~clear) | set); }
    ~MxcsrOverride() { _mm_setcsr(saved_); }
    MxcsrOverride(const MxcsrOverride&) = delete;
    MxcsrOverride& operator=(const MxcsrOverride&) = delete;

private:
    unsigned saved_;
};

bool names(const SelfTestReport& report, const std::string& word) {
    for (const std::string& failure : report.failures)
        if (failure.find(word) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("the rounding self-test fails, naming the flag, when MXCSR rounds down or flushes subnormals") {
    REQUIRE(run_rounding_self_test().passed);
    // Each state, the word its MXCSR failure must contain, and a word of an arithmetic check
    // that must fail too (the subnormal checks see FTZ and DAZ without reading MXCSR).
    struct Case {
        unsigned set;
        const char* flag;
        const char* arithmetic;
    };
    const unsigned rounding_control = 0x6000;
    for (const Case& c : {Case{0x2000, "rounding control", "MXCSR"}, Case{0x6000, "rounding control", "MXCSR"},
                          Case{0x8000, "FTZ", "2^-1022 * 3/4"}, Case{0x0040, "DAZ", "2^-1074 / 2"},
                          Case{0x8040, "FTZ", "2^-1074 * 2^-1074"}}) {
        SelfTestReport report;
        {
            const MxcsrOverride state(c.set, rounding_control);
            report = run_rounding_self_test();
        }
        std::string listed;
        for (const std::string& failure : report.failures) listed += failure + "\n";
        INFO("MXCSR bits " << c.set << " set; failures:\n" << listed);
        CHECK(!report.passed);
        CHECK(names(report, c.flag));
        CHECK(names(report, "MXCSR"));
        CHECK(names(report, c.arithmetic));
    }
    CHECK(run_rounding_self_test().passed);
}

#endif
