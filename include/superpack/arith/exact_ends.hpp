// An interval's endpoints exactly, as MPFR numbers and as "m*2^e" texts: how every certificate
// writes an endpoint, and the exact ends beside the decimals of the JSON output, from which the
// Python package builds its Fractions. Apart from arith/interval.hpp so that MPFR stays in the
// translation units that write endpoints.
#pragma once
#include <mpfr.h>

#include <string>

#include "superpack/arith/interval.hpp"

namespace superpack {

// "m*2^e" (integers m, e, m odd; "m" when e = 0; "0" for zero) for an MPFR number, exactly.
// Throws std::runtime_error for an infinity or NaN.
std::string dyadic_text(const mpfr_t x);

// The two ends of an interval at a precision that holds them exactly (53 bits for binary64;
// a ball's ends mid +- rad at its precision plus 64 guard bits, any rounding outward), with
// a zero end unsigned.
class ExactEnds {
public:
    explicit ExactEnds(const DInterval& x);
    explicit ExactEnds(const Ball& x);
    ~ExactEnds();
    ExactEnds(const ExactEnds&) = delete;
    ExactEnds& operator=(const ExactEnds&) = delete;

    mpfr_srcptr lo() const { return lo_; }
    mpfr_srcptr hi() const { return hi_; }

private:
    mpfr_t lo_, hi_;
};

}  // namespace superpack
