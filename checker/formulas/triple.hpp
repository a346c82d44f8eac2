// Integer coefficient triples (a, b, c) of lattice vectors a e1 + b e2 + c e3, as the lattice
// checks (lattice-check, family-lattice-check, audit) read, print and enumerate them.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "checker/verifier.hpp"

namespace superpack_checker {

using Triple = std::array<long, 3>;

std::string triple_text(const Triple& t);
// Three integers, each within +-max_coefficient (malformed at its own path, path[k], otherwise).
Triple read_triple(Context& context, const Json& node, const std::string& path);
// One of t, -t: the first nonzero coefficient positive.
bool canonical(const Triple& t);
// The one of t and -t that is canonical.
Triple representative(const Triple& t);
// The array node[key] of contact pairs (at `path`.key): 1 to max_contact_pairs triples, each the
// canonical one of its +-pair and none twice. c and -c give the same constraint (the gradient
// of the norm is odd), so a claim could otherwise list a pair in two ways and still verify.
std::vector<Triple> read_contact_pairs(Context& context, const Json& node, const std::string& key, const std::string& path);

}  // namespace superpack_checker
