#include "superpack/arith/exact_ends.hpp"

#include <gmpxx.h>

#include <stdexcept>

#include "superpack/arith/mpfr_bounds.hpp"

namespace superpack {

std::string dyadic_text(const mpfr_t x) {
    if (mpfr_zero_p(x)) return "0";
    if (!mpfr_number_p(x)) throw std::runtime_error("an interval end is not a finite number");
    mpz_class mantissa;
    long exponent = mpfr_get_z_2exp(mantissa.get_mpz_t(), x);
    // The shortest form: strip the mantissa's trailing zero bits into the exponent.
    const unsigned long zeros = mpz_scan1(mantissa.get_mpz_t(), 0);
    mpz_fdiv_q_2exp(mantissa.get_mpz_t(), mantissa.get_mpz_t(), zeros);
    exponent += static_cast<long>(zeros);
    if (exponent == 0) return mantissa.get_str();
    return mantissa.get_str() + "*2^" + std::to_string(exponent);
}

namespace {

template <class I>
void set_ends(mpfr_t lo, mpfr_t hi, const I& x, long bits) {
    mpfr_inits2(bits, lo, hi, static_cast<mpfr_ptr>(nullptr));
    get_bounds(lo, hi, x);
    // A file's "0" has no sign; decimals rendered from these ends use the same unsigned zero.
    if (mpfr_zero_p(lo)) mpfr_set_zero(lo, 1);
    if (mpfr_zero_p(hi)) mpfr_set_zero(hi, 1);
}

}  // namespace

ExactEnds::ExactEnds(const DInterval& x) { set_ends(lo_, hi_, x, 53); }
ExactEnds::ExactEnds(const Ball& x) { set_ends(lo_, hi_, x, x.precision() + 64); }
ExactEnds::~ExactEnds() { mpfr_clears(lo_, hi_, static_cast<mpfr_ptr>(nullptr)); }

}  // namespace superpack
