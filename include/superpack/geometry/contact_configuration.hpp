// Which of Minkowski's boundary configurations a lattice's contact vectors form (NOTES.md,
// "Densest lattice search"): a critical lattice of a 3-dimensional o-symmetric convex body has a
// basis b1, b2, b3 with {+-b1, +-b2, +-b3, +-(b2 - b3), +-(b3 - b1), +-(b1 - b2)} (six pairs) or
// {+-b1, +-b2, +-b3, +-(b1 + b2), +-(b2 + b3), +-(b3 + b1), +-(b1 + b2 + b3)} (seven pairs) on the
// boundary of 2K. Exact integer arithmetic on coefficient triples.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "superpack/geometry/lattice.hpp"

namespace superpack {

enum class Configuration { six_pairs, seven_pairs, other };

struct ConfigurationMatch {
    Configuration configuration = Configuration::other;
    std::size_t pairs = 0;               // +-pairs among the given vectors
    std::optional<Transform> basis;      // rows: b1, b2, b3 as triples in the given basis (|det| = 1)
};

// Contact vectors as coefficient triples (v and -v may both be listed).
ConfigurationMatch match_configuration(const std::vector<Coefficients>& contacts);
// "six pairs: Minkowski's {b1, b2, b3, b2-b3, b3-b1, b1-b2}", "seven pairs: ...", or "N pairs".
std::string configuration_text(const ConfigurationMatch& match);

}  // namespace superpack
