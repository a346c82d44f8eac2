// The exact arithmetic of lattice-check certificates, written again for the checker: the test
// ||v||_(2p) = 2 for a rational vector and a rational p, and the unimodular transform of a
// reduced basis (NOTES.md 5.3 and 5.6). Nothing here is shared with the producer.
#pragma once
#include <gmpxx.h>

#include <array>

namespace superpack_checker {

using RationalVector = std::array<mpq_class, 3>;
using RationalMatrix = std::array<RationalVector, 3>;
using IntegerMatrix = std::array<std::array<mpz_class, 3>, 3>;

// True when ||v||_(2p) = 2 is proved exactly: with a_i = |v_i|/2 over the nonzero coordinates and
// 2p = m/n in lowest terms, sum a_i^(m/n) = 1. False when it fails or is not proved (the exact
// powers would exceed 2^26 bits).
bool norm_is_exactly_two(const RationalVector& v, const mpq_class& two_p);

mpz_class determinant(const IntegerMatrix& u);
RationalMatrix product(const IntegerMatrix& u, const RationalMatrix& basis);  // u * basis, exactly

}  // namespace superpack_checker
