#pragma once

namespace superpack {
const char* version();     // the release, e.g. "0.1.0"
const char* git_commit();  // the commit the binary was built from, or "unknown"
}  // namespace superpack
