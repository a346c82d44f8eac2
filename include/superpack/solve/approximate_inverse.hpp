// A floating-point inverse for preconditioning (Krawczyk's C). Any matrix is a sound choice
// there; a good one only makes the operator contract. The linear algebra library stays out
// of every header that includes this one.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

namespace superpack {

// A square matrix of doubles, row-major.
class DoubleMatrix {
public:
    explicit DoubleMatrix(std::size_t n) : n_(n), entries_(n * n, 0.0) {}
    std::size_t size() const { return n_; }
    double& operator()(std::size_t i, std::size_t j) { return entries_[i * n_ + j]; }
    double operator()(std::size_t i, std::size_t j) const { return entries_[i * n_ + j]; }

private:
    std::size_t n_;
    std::vector<double> entries_;
};

// The inverse by LU with full pivoting, or nothing when the matrix is numerically singular.
std::optional<DoubleMatrix> approximate_inverse(const DoubleMatrix& matrix);

}  // namespace superpack
