#include "superpack/geometry/lattice_reduction.hpp"

#include <flint/fmpz_lll.h>
#include <flint/fmpz_mat.h>

#include <stdexcept>

namespace superpack {

Transform identity_transform() { return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; }

namespace {

struct IntegerMatrix {
    IntegerMatrix() { fmpz_mat_init(value, 3, 3); }
    ~IntegerMatrix() { fmpz_mat_clear(value); }
    IntegerMatrix(const IntegerMatrix&) = delete;
    IntegerMatrix& operator=(const IntegerMatrix&) = delete;
    fmpz* operator()(int i, int j) { return fmpz_mat_entry(value, i, j); }
    fmpz_mat_t value;
};

mpz_class to_mpz(const fmpz_t x) {
    mpz_class result;
    fmpz_get_mpz(result.get_mpz_t(), x);
    return result;
}

}  // namespace

BasisReduction reduce_basis(const Basis<Rational>& basis) {
    BasisReduction result;
    // L B is an integer matrix spanning the lattice scaled by L: the same transform reduces both.
    mpz_class common = 1;
    for (const auto& row : basis)
        for (const Rational& x : row) mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), x.get_den_mpz_t());
    IntegerMatrix scaled, transform;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const Rational entry = basis[i][j] * common;
            fmpz_set_mpz(scaled(i, j), entry.get_num_mpz_t());
        }
    if (fmpz_mat_rank(scaled.value) < 3) {
        result.reason = "the basis is singular";
        return result;
    }
    fmpz_mat_one(transform.value);
    fmpz_lll_t parameters;
    fmpz_lll_context_init_default(parameters);  // delta = 0.99, eta = 0.51, rows are the basis
    fmpz_lll(scaled.value, transform.value, parameters);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const mpz_class entry = to_mpz(transform(i, j));
            if (abs(entry) > reduction_entry_limit) {
                result.reason = "the basis is too skewed: its LLL transform has an entry of " +
                                std::to_string(mpz_sizeinbase(entry.get_mpz_t(), 2)) + " bits, beyond the limit 2^31";
                return result;
            }
            result.transform[i][j] = entry.get_si();
        }
    // The claims of this function, checked exactly rather than trusted: det U = +-1, and U B is
    // what LLL returned (divided by L).
    const Transform& u = result.transform;
    const mpz_class det = mpz_class(u[0][0]) * (mpz_class(u[1][1]) * u[2][2] - mpz_class(u[1][2]) * u[2][1]) -
                          mpz_class(u[0][1]) * (mpz_class(u[1][0]) * u[2][2] - mpz_class(u[1][2]) * u[2][0]) +
                          mpz_class(u[0][2]) * (mpz_class(u[1][0]) * u[2][1] - mpz_class(u[1][1]) * u[2][0]);
    if (abs(det) != 1) throw std::logic_error("LLL returned a transform of determinant " + det.get_str());
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            Rational entry = 0;
            for (int k = 0; k < 3; ++k) entry += u[i][k] * basis[k][j];
            if (entry * common != Rational(to_mpz(scaled(i, j)))) throw std::logic_error("LLL's transform does not give its basis");
            result.reduced[i][j] = entry;
        }
    result.done = true;
    return result;
}

std::array<long, 3> given_coefficients(const std::array<long, 3>& reduced, const Transform& transform) {
    std::array<long, 3> result{0, 0, 0};
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) result[j] += reduced[k] * transform[k][j];
    return result;
}

}  // namespace superpack
