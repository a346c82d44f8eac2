// Printing enclosures: the lower end rounded down and the upper end rounded up, so that the
// printed interval contains the computed one.
#pragma once
#include <string>

#include "superpack/interval.hpp"

namespace superpack {

struct DecimalEnclosure {
    std::string lo;
    std::string hi;
};

// Significant digits that keep the printed width within a few units of the true width.
int printed_digits(long bits);

DecimalEnclosure to_decimal(const DInterval& x, int digits);
DecimalEnclosure to_decimal(const Ball& x, int digits);
// Two exact MPFR ends, the lower rounded down and the upper up.
DecimalEnclosure to_decimal(const mpfr_t lo, const mpfr_t hi, int digits);
// Fixed-point form with `decimals` digits after the point, same outward rounding (tables).
DecimalEnclosure to_fixed(const DInterval& x, int decimals);
DecimalEnclosure to_fixed(const Ball& x, int decimals);

// Width of the enclosure as a decimal upper bound ("1.2e-31").
std::string width_text(const DInterval& x);
std::string width_text(const Ball& x);

}  // namespace superpack
