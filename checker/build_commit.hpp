#pragma once

namespace superpack_checker {
// The commit superpack-verify was built from (with "-modified" for local changes), or
// "unknown"; written at build time by cmake/commit.cmake.
const char* build_commit();
}  // namespace superpack_checker
