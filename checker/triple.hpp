// Integer coefficient triples (a, b, c) of lattice vectors a e1 + b e2 + c e3, as the lattice
// checks (lattice-check, family-lattice-check, audit) read, print and enumerate them.
#pragma once
#include <array>
#include <string>

#include "checker/verifier.hpp"

namespace superpack_checker {

using Triple = std::array<long, 3>;

std::string triple_text(const Triple& t);
Triple read_triple(Context& context, const Json& node, const std::string& path);
// One of t, -t: the first nonzero coefficient positive.
bool canonical(const Triple& t);

}  // namespace superpack_checker
