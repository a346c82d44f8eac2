// Reading a certificate's JSON under the checker's limits (checker/core/limits.hpp): a SAX parse that
// builds the document itself, so that it can refuse what nlohmann's own DOM parser accepts.
//   - nesting deeper than max_json_depth is refused before the deeper value is built;
//   - more than max_json_values values are refused before the next is built (the memory of a
//     document follows its values, about 110 bytes each, more than its bytes);
//   - a key that occurs twice in one object is refused (nlohmann keeps one of the two silently,
//     so the checker and a reader of the file could see different certificates).
// Each refusal names its path in the document (proof.cases[0].box) like the checker's rejections.
#pragma once
#include <istream>
#include <nlohmann/json.hpp>
#include <string>

namespace superpack_checker {

struct JsonReading {
    bool ok = false;
    nlohmann::json document;
    std::string path, message;  // where and why the reading failed
};

JsonReading read_json(const std::string& text);
JsonReading read_json(std::istream& stream);

// The first value of an in-memory document nested deeper than max_json_depth, found without
// recursion (for documents that did not come through read_json). Empty when there is none.
struct DepthExcess {
    bool found = false;
    std::string path, message;
};
DepthExcess find_depth_excess(const nlohmann::json& document);

}  // namespace superpack_checker
