// The JSON contract of superpack's output: every real is {"lo": "...", "hi": "..."} with lo
// rounded down and hi rounded up, and every document starts with the same header.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "superpack/families.hpp"

namespace superpack {

using Json = nlohmann::ordered_json;

Json enclosure_json(const DInterval& x);
Json enclosure_json(const Ball& x);

// {"tool", "version", "commit", "command"}, then "backend", "bits", "digits".
Json base_header_json(const std::string& command);
template <class Field>
Json header_json(const std::string& command, const Field& field, long digits) {
    Json header = base_header_json(command);
    header["backend"] = field.backend();
    header["bits"] = field.bits();
    header["digits"] = digits;
    return header;
}
// Parameters, basis, volume, determinant, phi, and the root proofs of one family at one p.
template <class I>
Json family_json(const FamilyLattice<I>& lattice);

template <class I>
Json root_leaf_json(const RootLeaf<I>& leaf);

}  // namespace superpack
