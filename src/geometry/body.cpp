#include "superpack/geometry/body.hpp"

#include <string>

namespace superpack {

Rational Superball::dual_exponent() const {
    const Rational two_p = 2 * p;
    if (two_p <= 1) throw std::domain_error("dual exponent: needs 2p > 1");
    Rational r = two_p / (two_p - 1);
    r.canonicalize();
    return r;
}

Superball make_superball(int dimension, const Rational& p) {
    if (dimension != 2 && dimension != 3)
        throw InputError("a superball has dimension 2 (superdisk) or 3, not " + std::to_string(dimension));
    if (p <= 0) throw InputError("a superball needs p > 0");
    return Superball{dimension, p};
}

}  // namespace superpack
