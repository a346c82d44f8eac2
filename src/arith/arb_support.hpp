// Internal helpers shared by both interval backends: exact endpoints of an arb_t and the
// monotonicity-aware Gamma enclosure. Not part of the public interface.
#pragma once
#include <arb.h>

namespace superpack::detail {

// Exact endpoints mid -/+ rad (no rounding: ARF_PREC_EXACT).
void lower_exact(arf_t lo, const arb_t x);
void upper_exact(arf_t hi, const arb_t x);

// Gamma and digamma over a ball x > 0. Where digamma (the log-derivative of Gamma) has one
// sign on x, Gamma is monotone and the endpoint values give the tight hull; otherwise
// Arb's own ball evaluation (derivative-bounded) is used. Digamma is increasing on (0, inf)
// because its derivative, trigamma, is positive there, so its hull is taken at the endpoints.
// Throws std::domain_error unless x > 0.
void enclose_gamma(arb_t result, const arb_t x, slong precision);
void enclose_digamma(arb_t result, const arb_t x, slong precision);

}  // namespace superpack::detail
