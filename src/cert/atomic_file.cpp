#include "superpack/cert/atomic_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>
#include <vector>

namespace superpack {

namespace {

const char* const partial_marker = ".superpack-partial-";

std::string system_error_text() { return std::strerror(errno); }

struct Location {
    std::string directory, name;
};

Location locate(const std::string& path) {
    const std::filesystem::path target(path);
    const std::string name = target.filename().string();
    if (path.empty() || name.empty() || name == "." || name == "..")
        throw FileError("cannot write '" + path + "': not a file name");
    return {target.has_parent_path() ? target.parent_path().string() : std::string("."), name};
}

bool process_is_gone(long pid) { return pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

// "<name>.superpack-partial-<pid>-XXXXXX" of a writer that no longer runs: regular files only.
void remove_stale_temporaries(const Location& location) {
    DIR* directory = opendir(location.directory.c_str());
    if (directory == nullptr) return;
    const std::string prefix = location.name + partial_marker;
    std::vector<std::string> stale;
    while (const dirent* entry = readdir(directory)) {
        const std::string entry_name = entry->d_name;
        if (entry_name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string rest = entry_name.substr(prefix.size());
        const auto dash = rest.find('-');
        if (dash == std::string::npos || dash == 0 || dash > 9 || rest.size() != dash + 7) continue;
        if (rest.find_first_not_of("0123456789") != dash) continue;
        if (!process_is_gone(std::stol(rest.substr(0, dash)))) continue;
        struct stat status {};
        const std::string full = location.directory + "/" + entry_name;
        if (lstat(full.c_str(), &status) == 0 && S_ISREG(status.st_mode)) stale.push_back(full);
    }
    closedir(directory);
    for (const std::string& file : stale) unlink(file.c_str());
}

bool write_all(int descriptor, const std::string& content) {
    std::size_t done = 0;
    while (done < content.size()) {
        const ssize_t written = write(descriptor, content.data() + done, content.size() - done);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) return false;
        done += static_cast<std::size_t>(written);
    }
    return true;
}

mode_t creation_mode() {
    const mode_t mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

// The rename is durable only once the directory entry is on disk. Some file systems cannot
// fsync a directory (EINVAL): there is nothing more to do then.
void sync_directory(const std::string& path, const std::string& target) {
    const int descriptor = open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (descriptor < 0) throw FileError("wrote '" + target + "' but cannot open its directory to sync it: " + system_error_text());
    const bool synced = fsync(descriptor) == 0 || errno == EINVAL;
    const std::string reason = synced ? "" : system_error_text();
    close(descriptor);
    if (!synced) throw FileError("wrote '" + target + "' but cannot sync its directory: " + reason);
}

// The directory exists, and the name is new or a regular file (lstat).
void require_target_rules(const std::string& path) {
    const Location location = locate(path);
    struct stat status {};
    if (stat(location.directory.c_str(), &status) != 0) {
        if (errno == ENOENT) throw FileError("cannot write '" + path + "': directory '" + location.directory + "' does not exist");
        throw FileError("cannot write '" + path + "': directory '" + location.directory + "': " + system_error_text());
    }
    if (!S_ISDIR(status.st_mode))
        throw FileError("cannot write '" + path + "': '" + location.directory + "' is not a directory");
    if (lstat(path.c_str(), &status) != 0) {
        if (errno == ENOENT) return;
        throw FileError("cannot write '" + path + "': " + system_error_text());
    }
    if (S_ISLNK(status.st_mode))
        throw FileError("refusing to write '" + path + "': it is a symbolic link (superpack replaces regular files only; "
                        "remove the link or name the file itself)");
    if (!S_ISREG(status.st_mode))
        throw FileError("refusing to write '" + path + "': it exists and is not a regular file (" +
                        (S_ISDIR(status.st_mode) ? "a directory" : S_ISFIFO(status.st_mode) ? "a FIFO"
                         : S_ISSOCK(status.st_mode) ? "a socket" : "a device") + ")");
}

// A fresh exclusive temporary file beside the target, open, with the mode a new file gets.
struct Temporary {
    std::string path;
    int descriptor;
};

Temporary create_temporary(const std::string& target) {
    require_target_rules(target);
    const Location location = locate(target);
    remove_stale_temporaries(location);
    std::string temporary = location.directory + "/" + location.name + partial_marker + std::to_string(getpid()) + "-XXXXXX";
    // mkostemp opens with O_CREAT | O_EXCL: it never follows a link planted at the name.
    const int descriptor = mkostemp(temporary.data(), O_CLOEXEC);
    if (descriptor < 0) throw FileError("cannot write '" + target + "': cannot create a temporary file: " + system_error_text());
    if (fchmod(descriptor, creation_mode()) != 0) {
        const std::string reason = system_error_text();
        close(descriptor);
        unlink(temporary.c_str());
        throw FileError("cannot write '" + target + "': " + reason);
    }
    return {temporary, descriptor};
}

// Syncs and closes the temporary and renames it over the target; `written` false (or any
// failure) removes it instead and throws FileError with `reason`.
void commit(const Temporary& temporary, const std::string& target, bool written, std::string reason) {
    if (written && fsync(temporary.descriptor) != 0) {
        written = false;
        reason = system_error_text();
    }
    if (close(temporary.descriptor) != 0 && written) {
        written = false;
        reason = system_error_text();
    }
    if (!written) {
        unlink(temporary.path.c_str());
        throw FileError("cannot write '" + target + "': " + reason);
    }
    if (rename(temporary.path.c_str(), target.c_str()) != 0) {
        const std::string rename_reason = system_error_text();
        unlink(temporary.path.c_str());
        throw FileError("cannot write '" + target + "': " + rename_reason);
    }
    sync_directory(locate(target).directory, target);
}

// Whether the name still holds the file the descriptor has open (a regular file).
bool same_file(const std::string& path, int descriptor) {
    struct stat named {}, opened {};
    return lstat(path.c_str(), &named) == 0 && fstat(descriptor, &opened) == 0 && S_ISREG(named.st_mode) &&
           named.st_dev == opened.st_dev && named.st_ino == opened.st_ino;
}

}  // namespace

void require_writable_target(const std::string& path) {
    // The rules say nothing of permissions or of file systems that take no new file (read-only,
    // /proc): a temporary created and removed beside the target does.
    const Temporary probe = create_temporary(path);
    close(probe.descriptor);
    unlink(probe.path.c_str());
}

void write_atomically(const std::string& path, const std::string& content) {
    const Temporary temporary = create_temporary(path);
    const bool written = write_all(temporary.descriptor, content);
    commit(temporary, path, written, written ? "" : system_error_text());
}

void write_atomically_by(const std::string& path, const std::function<void(const std::string& temporary)>& fill) {
    const Temporary temporary = create_temporary(path);
    try {
        fill(temporary.path);
    } catch (...) {
        close(temporary.descriptor);
        unlink(temporary.path.c_str());
        throw;
    }
    const bool same = same_file(temporary.path, temporary.descriptor);
    commit(temporary, path, same, "its temporary file '" + temporary.path + "' was replaced while it was written");
}

void create_default_directory(const std::string& path) {
    if (mkdir(path.c_str(), 0777) == 0) return;
    if (errno != EEXIST) throw FileError("cannot create the directory '" + path + "': " + system_error_text());
    struct stat status {};
    if (stat(path.c_str(), &status) != 0 || !S_ISDIR(status.st_mode))
        throw FileError("cannot use '" + path + "' as the output directory: it exists and is not a directory");
}

}  // namespace superpack
