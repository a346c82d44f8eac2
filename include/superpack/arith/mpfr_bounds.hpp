// Interval endpoints as MPFR numbers and MPFR numbers as decimals, for decimal output and
// comparisons with MPFR references.
// Apart from arith/interval.hpp so that only the code that prints or compares pulls MPFR.
#pragma once
#include <mpfr.h>

#include "superpack/arith/decimal.hpp"
#include "superpack/arith/interval.hpp"

namespace superpack {

// Endpoints rounded outward to the precision of lo and hi.
void get_bounds(mpfr_t lo, mpfr_t hi, const DInterval& x);
void get_bounds(mpfr_t lo, mpfr_t hi, const Ball& x);
// Two exact MPFR ends as decimals, the lower rounded down and the upper up.
DecimalEnclosure to_decimal(const mpfr_t lo, const mpfr_t hi, int digits);

}  // namespace superpack
