// Result and certificate files: a planted name never redirects the write, a target that is
// not a regular file or a new name is refused, and a killed writer leaves the target whole
// and its temporary removable.
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "superpack/cert/atomic_file.hpp"
#include "support.hpp"

namespace {

namespace fs = std::filesystem;

// A fresh empty directory per test, removed afterwards.
struct Scratch {
    fs::path directory;
    Scratch() {
        std::string pattern = (fs::temp_directory_path() / "superpack-atomic-XXXXXX").string();
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        directory = pattern;
    }
    ~Scratch() { fs::remove_all(directory); }
    std::string operator/(const std::string& name) const { return (directory / name).string(); }
    std::vector<std::string> names() const {
        std::vector<std::string> result;
        for (const auto& entry : fs::directory_iterator(directory)) result.push_back(entry.path().filename().string());
        std::sort(result.begin(), result.end());
        return result;
    }
};

std::string contents(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), {}};
}

void put(const std::string& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary);
    file << text;
}

// The pid of a process that has exited and been reaped.
pid_t dead_pid() {
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) _exit(0);
    int status = 0;
    waitpid(child, &status, 0);
    return child;
}

}  // namespace

TEST_CASE("a link planted at the old temporary name PATH.tmp.<pid> is not followed") {
    const Scratch scratch;
    const std::string target = scratch / "report.json", victim = scratch / "victim";
    put(victim, "precious");
    fs::create_symlink(victim, target + ".tmp." + std::to_string(getpid()));
    superpack::write_atomically(target, "new\n");
    CHECK(contents(victim) == "precious");
    CHECK(contents(target) == "new\n");
}

TEST_CASE("a symbolic link at the target itself is refused and left alone") {
    const Scratch scratch;
    const std::string target = scratch / "certificate.json", victim = scratch / "victim";
    put(victim, "precious");
    fs::create_symlink(victim, target);
    CHECK_THROWS_AS(superpack::write_atomically(target, "new\n"), std::runtime_error);
    CHECK(fs::is_symlink(target));
    CHECK(contents(victim) == "precious");
    // A dangling link too: writing through it would create its target.
    const std::string dangling = scratch / "dangling.json";
    fs::create_symlink(scratch / "nowhere", dangling);
    CHECK_THROWS_AS(superpack::write_atomically(dangling, "new\n"), std::runtime_error);
    CHECK(!fs::exists(scratch / "nowhere"));
}

TEST_CASE("a FIFO, a device or a directory at the target is refused, not replaced") {
    const Scratch scratch;
    const std::string fifo = scratch / "fifo.json";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    CHECK_THROWS_AS(superpack::write_atomically(fifo, "new\n"), std::runtime_error);
    CHECK(fs::is_fifo(fifo));
    const std::string directory = scratch / "directory.json";
    fs::create_directory(directory);
    CHECK_THROWS_AS(superpack::write_atomically(directory, "new\n"), std::runtime_error);
    CHECK(fs::is_directory(directory));
    // A character device like /dev/null (1, 3), when this process may create one.
    const std::string device = scratch / "null.json";
    if (mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
        CHECK_THROWS_AS(superpack::write_atomically(device, "new\n"), std::runtime_error);
        CHECK(fs::is_character_file(device));
    } else {
        WARN("mknod not permitted here: the device case is covered by the FIFO and directory cases");
    }
    for (const std::string& name : scratch.names()) CHECK(name.find("partial") == std::string::npos);  // no temporary left
}

TEST_CASE("a missing directory is refused, not created") {
    const Scratch scratch;
    const std::string target = scratch / "missing/deeper/audit-C0.json";
    CHECK_THROWS_AS(superpack::write_atomically(target, "new\n"), std::runtime_error);
    CHECK(!fs::exists(scratch / "missing"));
    // A regular file where the directory should be.
    put(scratch / "file", "x");
    CHECK_THROWS_AS(superpack::write_atomically(scratch / "file/audit-C0.json", "new\n"), std::runtime_error);
    CHECK(contents(scratch / "file") == "x");
}

TEST_CASE("a stale temporary of a writer that no longer runs is removed; a live writer's is kept") {
    const Scratch scratch;
    const std::string target = scratch / "report.json";
    const std::string stale = target + ".superpack-partial-" + std::to_string(dead_pid()) + "-a1B2c3";
    const std::string live = target + ".superpack-partial-" + std::to_string(getppid()) + "-d4E5f6";
    const std::string other = scratch / "other.json.superpack-partial-1-g7H8i9";  // another target's
    for (const auto& path : {stale, live, other}) put(path, "half");
    superpack::write_atomically(target, "new\n");
    CHECK(!fs::exists(stale));
    CHECK(fs::exists(live));
    CHECK(fs::exists(other));
    CHECK(contents(target) == "new\n");
}

TEST_CASE("a writer killed while writing leaves the target whole, and its temporary is removed next time") {
    const Scratch scratch;
    const std::string target = scratch / "report.json";
    superpack::write_atomically(target, "old\n");
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        // The kernel kills the writer with SIGXFSZ in the middle of the file: a kill at a known point.
        std::signal(SIGXFSZ, SIG_DFL);
        const rlimit no_core{0, 0}, small_files{1 << 16, 1 << 16};
        setrlimit(RLIMIT_CORE, &no_core);
        setrlimit(RLIMIT_FSIZE, &small_files);
        try {
            superpack::write_atomically(target, std::string(1 << 20, 'x'));
        } catch (...) {
        }
        _exit(0);
    }
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    REQUIRE(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGXFSZ);
    CHECK(contents(target) == "old\n");
    CHECK(scratch.names().size() == 2);  // the target and the killed writer's temporary
    superpack::write_atomically(target, "next\n");
    CHECK(scratch.names() == std::vector<std::string>{"report.json"});
    CHECK(contents(target) == "next\n");
}

TEST_CASE("a new file gets the usual permissions (0666 less the umask), not mkstemp's 0600") {
    const Scratch scratch;
    const mode_t mask = umask(022);
    superpack::write_atomically(scratch / "report.json", "new\n");
    umask(mask);
    struct stat status {};
    REQUIRE(stat((scratch / "report.json").c_str(), &status) == 0);
    CHECK((status.st_mode & 0777) == 0644);
}
