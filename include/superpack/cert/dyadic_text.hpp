// "m*2^e" (integers m, e; "0" for zero) for an MPFR number, exactly: how every certificate
// writes an interval endpoint. Apart from cert/certificate.hpp so that MPFR stays in the
// translation units that write endpoints.
#pragma once
#include <mpfr.h>

#include <string>

namespace superpack {

std::string dyadic_text(const mpfr_t x);

}  // namespace superpack
