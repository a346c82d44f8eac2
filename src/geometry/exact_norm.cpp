#include "superpack/geometry/exact_norm.hpp"

#include <optional>
#include <vector>

namespace superpack {

namespace {

// r^(1/n) when the positive rational r != 1 is the n-th power of a rational. Its root then has
// a numerator or denominator of at least 2, so r has one of at least n + 1 bits: a larger n
// (even one beyond 64 bits) has no root to look for.
std::optional<Rational> exact_root(const Rational& r, const mpz_class& n) {
    const std::size_t bits = std::max(mpz_sizeinbase(r.get_num_mpz_t(), 2), mpz_sizeinbase(r.get_den_mpz_t(), 2));
    if (!n.fits_ulong_p() || n.get_ui() > bits) return std::nullopt;
    mpz_class numerator, denominator;
    if (mpz_root(numerator.get_mpz_t(), r.get_num_mpz_t(), n.get_ui()) == 0) return std::nullopt;
    if (mpz_root(denominator.get_mpz_t(), r.get_den_mpz_t(), n.get_ui()) == 0) return std::nullopt;
    return Rational(numerator, denominator);
}

// sum b_i^m = 1 for two or three rationals 0 < b_i < 1: with d the common denominator and
// c_i = b_i d, sum c_i^m = d^m in integers.
ExactNormDecision power_sum_is_one(const std::vector<Rational>& b, const mpz_class& m) {
    mpz_class d = 1;
    for (const Rational& x : b) mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), x.get_den_mpz_t());
    std::vector<mpz_class> c;
    for (const Rational& x : b) c.push_back(x.get_num() * (d / x.get_den()));
    // Unequal modulo some M means unequal: the Mersenne primes 2^61 - 1 and 2^89 - 1 decide
    // almost every such case with numbers of 89 bits, whatever m.
    for (const unsigned long exponent : {61ul, 89ul}) {
        const mpz_class modulus = (mpz_class(1) << exponent) - 1;
        mpz_class sum = 0, power;
        for (const mpz_class& x : c) {
            mpz_powm(power.get_mpz_t(), x.get_mpz_t(), m.get_mpz_t(), modulus.get_mpz_t());
            sum += power;
        }
        mpz_powm(power.get_mpz_t(), d.get_mpz_t(), m.get_mpz_t(), modulus.get_mpz_t());
        if ((sum - power) % modulus != 0)
            return {ExactNorm::not_two, "sum |v_i/2|^(2p) differs from 1 modulo 2^" + std::to_string(exponent) + " - 1"};
    }
    const std::size_t bits = mpz_sizeinbase(d.get_mpz_t(), 2);
    if (!m.fits_ulong_p() || m.get_ui() > exact_norm_bit_budget / bits)
        return {ExactNorm::unknown, "equal to 1 modulo two primes, and the exact powers would exceed " +
                                        std::to_string(exact_norm_bit_budget) + " bits"};
    mpz_class sum = 0, power;
    for (const mpz_class& x : c) {
        mpz_pow_ui(power.get_mpz_t(), x.get_mpz_t(), m.get_ui());
        sum += power;
    }
    mpz_pow_ui(power.get_mpz_t(), d.get_mpz_t(), m.get_ui());
    if (sum == power) return {ExactNorm::two, "sum |v_i/2|^(2p) = 1 in integers"};
    return {ExactNorm::not_two, "sum |v_i/2|^(2p) != 1 in integers"};
}

}  // namespace

// With a_i = |v_i|/2 over the nonzero coordinates and 2p = m/n in lowest terms, the question is
// sum a_i^(m/n) = 1 (NOTES.md 5.3).
ExactNormDecision decide_norm_is_two(const std::array<Rational, 3>& v, const Rational& p) {
    Rational two_p = 2 * p;
    two_p.canonicalize();
    const mpz_class& m = two_p.get_num();
    const mpz_class& n = two_p.get_den();
    std::vector<Rational> a;
    for (const Rational& x : v)
        if (x != 0) a.push_back(abs(x) / 2);
    if (a.empty()) return {ExactNorm::not_two, "the zero vector"};
    int ones = 0;
    for (const Rational& x : a) {
        if (x > 1) return {ExactNorm::not_two, "a coordinate exceeds 2 in size"};
        if (x == 1) ++ones;
    }
    if (ones > 0) {
        if (a.size() == 1) return {ExactNorm::two, "one nonzero coordinate, of size 2"};
        return {ExactNorm::not_two, "a coordinate of size 2 and another nonzero one"};
    }
    if (a.size() == 1) return {ExactNorm::not_two, "one nonzero coordinate, of size below 2"};
    // n > 1: real n-th roots of positive rationals whose ratios are not n-th powers are linearly
    // independent over Q (Besicovitch 1940, Mordell 1953). Grouping the a_i^(m/n) = (a_i^m)^(1/n)
    // by the class of a_i^m modulo n-th powers, every class but that of 1 would need a zero sum
    // of positive terms; so the sum can be 1 only if every a_i^m, hence (gcd(m, n) = 1) every
    // a_i, is the n-th power of a rational b_i, and then sum a_i^(m/n) = sum b_i^m.
    std::vector<Rational> b;
    for (const Rational& x : a) {
        if (n == 1) {
            b.push_back(x);
            continue;
        }
        const std::optional<Rational> root = exact_root(x, n);
        if (!root) return {ExactNorm::not_two, "|v_i/2|^(2p) is irrational for some i, and such radicals cannot sum to 1"};
        b.push_back(*root);
    }
    return power_sum_is_one(b, m);
}

}  // namespace superpack
