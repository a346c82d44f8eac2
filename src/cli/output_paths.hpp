// The files a command writes, checked together before any work (README, "Files"): a path option
// refuses an empty name when it is parsed, and require_output_paths refuses a target that cannot
// be written and two options naming one file, each naming its option (exit 2).
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace superpack::cli {

// Adds the option `name` for a file or directory the command writes, held in `path`.
CLI::Option* add_output_option(CLI::App& command, const std::string& name, std::string& path, const std::string& help);

// A file a command will write, and the option that named it (or the one whose directory holds it).
struct OutputPath {
    std::string option, path;  // path empty: the option was not given
};

// Throws InputError, naming the option, unless every given path can be written
// (require_writable_target) and no two of them name one file.
void require_output_paths(const std::vector<OutputPath>& paths);

}  // namespace superpack::cli
