// Exact reduction of a lattice basis with rational entries: LLL (FLINT's fmpz_lll on the integer
// matrix L B, L the common denominator of the entries), with the unimodular transform U that
// maps the given basis to the reduced one. U is integral with det U = +-1 and U B is the reduced
// basis exactly: both are checked in exact arithmetic (NOTES.md section 5.6).
#pragma once
#include <array>
#include <string>

#include "superpack/arith/exact.hpp"
#include "superpack/geometry/lattice_basis.hpp"

namespace superpack {

// Integer rows: row i of the reduced basis is sum_k U[i][k] e_k.
using Transform = std::array<std::array<long, 3>, 3>;

Transform identity_transform();

// |U_ij| <= 2^31: coefficients in the reduced basis (at most 10^7 in size, the enumeration's
// limit) then map to coefficients in the given basis without overflow.
constexpr long reduction_entry_limit = 1l << 31;

struct BasisReduction {
    bool done = false;  // false: U would exceed the limit, or the basis is singular (reason says which)
    std::string reason;
    Transform transform = identity_transform();
    Basis<Rational> reduced{};
};

BasisReduction reduce_basis(const Basis<Rational>& basis);

// The coefficients c U, in the given basis, of the vector with coefficients c in the reduced one.
std::array<long, 3> given_coefficients(const std::array<long, 3>& reduced, const Transform& transform);

}  // namespace superpack
