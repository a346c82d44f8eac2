#include "output_paths.hpp"

#include <filesystem>

#include "superpack/arith/exact.hpp"
#include "superpack/cert/atomic_file.hpp"

namespace superpack::cli {

namespace {

// One name per file: the directory resolved (links, "..", "."), which exists once the target
// passed require_writable_target, and the file's own name.
std::filesystem::path resolved(const std::string& path) {
    const std::filesystem::path target(path);
    const std::filesystem::path directory = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    return std::filesystem::canonical(directory) / target.filename();
}

}  // namespace

CLI::Option* add_output_option(CLI::App& command, const std::string& name, std::string& path, const std::string& help) {
    // An empty name would be taken for "not given" and silently write nothing.
    const CLI::Validator named(
        [](std::string& text) { return text.empty() ? std::string("an empty name; give a path") : std::string(); }, "", "named");
    return command.add_option(name, path, help)->check(named);
}

void require_output_paths(const std::vector<OutputPath>& paths) {
    std::vector<std::pair<std::filesystem::path, std::string>> seen;
    for (const OutputPath& output : paths) {
        if (output.path.empty()) continue;
        try {
            require_writable_target(output.path);
        } catch (const FileError& error) {
            throw InputError(output.option + ": " + error.what());
        }
        const std::filesystem::path file = resolved(output.path);
        for (const auto& [other, option] : seen)
            if (other == file)
                throw InputError(output.option + " '" + output.path + "' names the same file as " + option +
                                 ": each output needs its own file");
        seen.emplace_back(file, output.option);
    }
}

}  // namespace superpack::cli
