#include "superpack/cert/output_header.hpp"

#include "superpack/cert/version.hpp"

namespace superpack {

Json base_header_json(const std::string& command) {
    return Json{{"tool", "superpack"}, {"version", version()}, {"commit", git_commit()}, {"command", command}};
}

}  // namespace superpack
