#include "checker/formulas/equations_lattice.hpp"

#include <vector>

namespace superpack_checker {

namespace {

constexpr unsigned long kBitBudget = 1ul << 26;

unsigned long bits(const mpz_class& x) { return mpz_sizeinbase(x.get_mpz_t(), 2); }

// The rational whose n-th power is x, if there is one (x > 0, x != 1: its root has a part of at
// least 2, so x has a part of more than n bits).
bool nth_root(mpq_class& root, const mpq_class& x, const mpz_class& n) {
    const unsigned long size = std::max(bits(x.get_num()), bits(x.get_den()));
    if (!n.fits_ulong_p() || n.get_ui() >= size) return false;
    mpz_class top, bottom;
    if (mpz_root(top.get_mpz_t(), x.get_num_mpz_t(), n.get_ui()) == 0) return false;
    if (mpz_root(bottom.get_mpz_t(), x.get_den_mpz_t(), n.get_ui()) == 0) return false;
    root = mpq_class(top, bottom);
    return true;
}

}  // namespace

// Cases (NOTES.md 5.3): a coordinate above 2 in size gives a norm above 2; one of size exactly 2
// gives norm 2 iff it is the only nonzero one; otherwise every a_i < 1. For n > 1 the sum can be
// 1 only if every a_i is an n-th power b_i^n (linear independence of radicals), and then the sum
// is sum b_i^m. An integer exponent m is decided by clearing denominators.
bool norm_is_exactly_two(const RationalVector& v, const mpq_class& two_p) {
    const mpz_class& m = two_p.get_num();
    const mpz_class& n = two_p.get_den();
    std::vector<mpq_class> parts;
    for (const mpq_class& x : v)
        if (x != 0) parts.push_back(abs(x) / 2);
    bool unit = false;
    for (const mpq_class& a : parts) {
        if (a > 1) return false;
        unit = unit || a == 1;
    }
    if (unit || parts.size() < 2) return unit && parts.size() == 1;
    if (n != 1)
        for (mpq_class& a : parts)
            if (!nth_root(a, a, n)) return false;
    mpz_class common = 1;
    for (const mpq_class& a : parts) mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), a.get_den_mpz_t());
    if (!m.fits_ulong_p() || m.get_ui() > kBitBudget / bits(common)) return false;
    mpz_class sum = 0, term;
    for (const mpq_class& a : parts) {
        const mpz_class scaled = a.get_num() * (common / a.get_den());
        mpz_pow_ui(term.get_mpz_t(), scaled.get_mpz_t(), m.get_ui());
        sum += term;
    }
    mpz_pow_ui(term.get_mpz_t(), common.get_mpz_t(), m.get_ui());
    return sum == term;
}

mpz_class determinant(const IntegerMatrix& u) {
    return u[0][0] * (u[1][1] * u[2][2] - u[1][2] * u[2][1]) - u[0][1] * (u[1][0] * u[2][2] - u[1][2] * u[2][0]) +
           u[0][2] * (u[1][0] * u[2][1] - u[1][1] * u[2][0]);
}

RationalMatrix product(const IntegerMatrix& u, const RationalMatrix& basis) {
    RationalMatrix result;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) result[i][j] = u[i][0] * basis[0][j] + u[i][1] * basis[1][j] + u[i][2] * basis[2][j];
    return result;
}

}  // namespace superpack_checker
