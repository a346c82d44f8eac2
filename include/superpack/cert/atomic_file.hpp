// Writing result files so that a reader never sees half of one: write a temporary file
// beside the target, flush it, then rename over the target (atomic on POSIX).
#pragma once
#include <string>

namespace superpack {

// Creates missing parent directories. Throws std::runtime_error naming the path on failure.
void write_atomically(const std::string& path, const std::string& content);

}  // namespace superpack
