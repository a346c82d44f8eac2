// exp, log and Gamma of binary64 intervals, from table-driven series whose remainders are
// bounded in closed form and whose arithmetic is outward rounded: rigorous without a call
// to libm and without a round trip through Arb for each endpoint (NOTES.md section 1).
#pragma once
#include <arb.h>

#include "superpack/arith/interval_double.hpp"

namespace superpack::detail {

// A ball rounded outward to binary64 intervals, and f(x) by Arb at 64 bits so rounded: for
// the constants of the tables and the rare arguments outside their ranges (interval_double.cpp).
DInterval from_arb(const arb_t x);
using ArbFunction = void (*)(arb_t, const arb_t, slong);
DInterval through_arb(const DInterval& x, ArbFunction f);

// exp(x) and log(x) (x > 0) over an interval x.
DInterval enclose_exp(const DInterval& x);
DInterval enclose_log(const DInterval& x);

// Gamma from Taylor series of log Gamma on [1, 2] and the recurrence Gamma(x + 1) = x Gamma(x),
// for a narrow x in [1/16, 8) between two integers (gamma_series_applies); elsewhere Arb.
bool gamma_series_applies(const DInterval& x);
DInterval enclose_gamma_series(const DInterval& x);

}  // namespace superpack::detail
