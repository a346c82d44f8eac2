#include "checker/formulas/positive_definite.hpp"

namespace superpack_checker {

std::size_t first_unproved_pivot(const std::vector<std::vector<Real>>& m) {
    const std::size_t n = m.size();
    const mpfr_prec_t precision = m[0][0].precision();
    std::vector<std::vector<Real>> l(n, std::vector<Real>(n, Real(precision)));
    std::vector<Real> d;
    for (std::size_t j = 0; j < n; ++j) {
        Real pivot = m[j][j];
        for (std::size_t k = 0; k < j; ++k) pivot = pivot - l[j][k] * l[j][k] * d[k];
        if (!positive(pivot)) return j;
        d.push_back(pivot);
        for (std::size_t i = j + 1; i < n; ++i) {
            Real sum = m[i][j];
            for (std::size_t k = 0; k < j; ++k) sum = sum - l[i][k] * l[j][k] * d[k];
            l[i][j] = sum / pivot;
        }
    }
    return n;
}

std::size_t first_unproved_cholesky_pivot(const std::vector<std::vector<Real>>& m) {
    const std::size_t n = m.size();
    const mpfr_prec_t precision = m[0][0].precision();
    std::vector<std::vector<Real>> l(n, std::vector<Real>(n, Real(precision)));
    for (std::size_t j = 0; j < n; ++j) {
        Real pivot = m[j][j];
        for (std::size_t k = 0; k < j; ++k) pivot = pivot - square(l[j][k]);
        if (!positive(pivot)) return j;
        l[j][j] = sqrt(pivot);
        for (std::size_t i = j + 1; i < n; ++i) {
            Real sum = m[i][j];
            for (std::size_t k = 0; k < j; ++k) sum = sum - l[i][k] * l[j][k];
            l[i][j] = sum / l[j][j];
        }
    }
    return n;
}

}  // namespace superpack_checker
