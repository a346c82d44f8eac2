#include "superpack/solve/approximate_inverse.hpp"

#include <Eigen/Dense>

namespace superpack {

std::optional<DoubleMatrix> approximate_inverse(const DoubleMatrix& matrix) {
    const auto n = static_cast<Eigen::Index>(matrix.size());
    Eigen::MatrixXd dense(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) dense(i, j) = matrix(i, j);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(dense);
    if (!lu.isInvertible()) return std::nullopt;
    const Eigen::MatrixXd inverse = lu.inverse();
    DoubleMatrix result(matrix.size());
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) result(i, j) = inverse(i, j);
    return result;
}

}  // namespace superpack
