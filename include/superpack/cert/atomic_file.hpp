// Writing result files so that a reader never sees half of one, and so that a planted name
// cannot redirect the write: the content goes to a temporary file created exclusively
// (O_CREAT | O_EXCL | O_NOFOLLOW, a random suffix) in the target's own directory, is fsynced,
// renamed over the target, and the directory is fsynced.
#pragma once
#include <functional>
#include <stdexcept>
#include <string>

namespace superpack {

// A path superpack refuses to write, or a write that failed; the message names the path.
// The CLI maps it to exit code 2.
struct FileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws FileError unless `path` can be a result file: its directory exists (missing
// directories are never created here), the name is new or a regular file (lstat: a symbolic
// link, device, FIFO, socket or directory at the name is refused), and a temporary file can be
// created beside it (it is removed at once). Commands call it before a long computation so that
// a bad path fails at once.
void require_writable_target(const std::string& path);

// The temporaries are named "<name>.superpack-partial-<pid>-XXXXXX". A writer killed before
// its rename leaves one behind; the next write to the same target removes those of processes
// that no longer run (regular files only, never following a link).
void write_atomically(const std::string& path, const std::string& content);

// The same for content another program writes by name (gnuplot's PNG): `fill` gets the path of
// the fresh, empty temporary file and must leave it complete; then it is synced and renamed
// over `path`, but only if the name still holds the file created for it. When `fill` throws, the
// temporary is removed and the exception passes on.
void write_atomically_by(const std::string& path, const std::function<void(const std::string& temporary)>& fill);

// Creates the one directory `path` if it is missing (its parent must exist): for the default
// out/ of report and audit only; a directory the user names must exist.
void create_default_directory(const std::string& path);

}  // namespace superpack
