// Reads a certificate's JSON text. JSON leaves a repeated key in one object undefined and
// nlohmann keeps the last one silently, so a file could carry two claim texts of which a reader
// sees one and the checker another. Every key is therefore unique in its object, or the file is
// rejected (malformed) at the repeated key's path ("claim.text", "proof.cases[1].box").
#pragma once
#include <string>

#include "checker/verifier.hpp"

namespace superpack_checker {

// Throws Rejection{malformed, path, ...} at a repeated key, Json::parse_error on bad JSON.
Json read_json(const std::string& text);

}  // namespace superpack_checker
