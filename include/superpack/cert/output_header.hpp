// The head every JSON document of superpack starts with, certificates included: which tool,
// version and commit made it, from which command, with which backend and precision.
#pragma once
#include <string>

#include "superpack/arith/enclosure_json.hpp"

namespace superpack {

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

}  // namespace superpack
