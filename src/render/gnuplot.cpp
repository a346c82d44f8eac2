#include "gnuplot.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <locale>
#include <memory>
#include <sstream>
#include <thread>

#include "superpack/cert/atomic_file.hpp"
#include "superpack/render/render_error.hpp"

extern char** environ;

namespace superpack::gnuplot {

namespace {

// A plot of a few thousand points takes gnuplot well under a second, a packing picture a few
// seconds; a gnuplot that neither reads nor exits in this time is stopped, so that the command
// cannot hang on it.
constexpr auto gnuplot_time_limit = std::chrono::seconds(120);
const char png_signature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};

std::string system_error_text() { return std::strerror(errno); }

// The last line of gnuplot's stderr that says something: its error message.
std::string last_line(FILE* file) {
    std::rewind(file);
    std::string line, last;
    int c;
    while ((c = std::fgetc(file)) != EOF) {
        if (c != '\n') {
            line += static_cast<char>(c);
            continue;
        }
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
        line.clear();
    }
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    const std::size_t start = last.find_first_not_of(" \t");
    return start == std::string::npos ? std::string() : last.substr(start);
}

struct Descriptor {
    int value = -1;
    ~Descriptor() { reset(); }
    void reset() {
        if (value >= 0) close(value);
        value = -1;
    }
};

// Writes all of `text` to the pipe (non-blocking) before `deadline`; false when gnuplot closed
// its end (EPIPE: it exited, its status says why) or the time ran out.
bool feed(int descriptor, const std::string& text, std::chrono::steady_clock::time_point deadline) {
    std::size_t done = 0;
    while (done < text.size()) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return false;
        pollfd ready{descriptor, POLLOUT, 0};
        if (poll(&ready, 1, static_cast<int>(left.count())) < 0 && errno != EINTR) return false;
        const ssize_t written = write(descriptor, text.data() + done, text.size() - done);
        if (written < 0 && (errno == EAGAIN || errno == EINTR)) continue;
        if (written < 0) return false;
        done += static_cast<std::size_t>(written);
    }
    return true;
}

// gnuplot's exit status, waiting until `deadline`; after it, gnuplot is killed.
int wait_for(pid_t child, std::chrono::steady_clock::time_point deadline) {
    int status = 0;
    for (;;) {
        const pid_t waited = waitpid(child, &status, WNOHANG);
        if (waited == child) return status;
        if (waited < 0 && errno != EINTR) throw RenderError("cannot wait for gnuplot: " + system_error_text());
        if (std::chrono::steady_clock::now() >= deadline) {
            kill(child, SIGKILL);
            while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
            }
            throw RenderError("gnuplot did not finish within " + std::to_string(gnuplot_time_limit.count()) + " s and was stopped");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
}

// SIGPIPE ignored while this lives, so that writing to a gnuplot that quit is EPIPE, not death.
struct IgnoredBrokenPipe {
    struct sigaction previous {};
    IgnoredBrokenPipe() {
        struct sigaction ignore {};
        ignore.sa_handler = SIG_IGN;
        sigemptyset(&ignore.sa_mask);
        sigaction(SIGPIPE, &ignore, &previous);
    }
    ~IgnoredBrokenPipe() { sigaction(SIGPIPE, &previous, nullptr); }
};

bool starts_as_png(const std::string& path) {
    const int descriptor = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (descriptor < 0) return false;
    char head[sizeof png_signature] = {};
    const bool png = read(descriptor, head, sizeof head) == static_cast<ssize_t>(sizeof head) &&
                     std::memcmp(head, png_signature, sizeof head) == 0;
    close(descriptor);
    return png;
}

}  // namespace

std::string quoted(const std::string& text) {
    if (text.find_first_of("\n\r") != std::string::npos)
        throw RenderError("cannot plot: '" + text + "' holds a line break");
    std::string result = "'";
    for (char c : text) result += c == '\'' ? std::string("''") : std::string(1, c);
    return result + "'";
}

std::string output_path(const std::string& path) { return path.front() == '/' ? path : "./" + path; }

std::string number(double value, int digits) {
    std::ostringstream text;
    text.imbue(std::locale::classic());
    text.precision(digits);
    text << value;
    return text.str();
}

// Runs gnuplot (found in PATH, no shell) with `script` on its stdin, its stdout discarded and
// its stderr kept for the message; returns only when it exited 0.
void run(const std::string& text) {
    const std::unique_ptr<FILE, int (*)(FILE*)> errors(std::tmpfile(), &std::fclose);
    if (!errors) throw RenderError("cannot run gnuplot: no temporary file for its messages: " + system_error_text());
    int ends[2];
    if (pipe2(ends, O_CLOEXEC) != 0) throw RenderError("cannot run gnuplot: " + system_error_text());
    Descriptor read_end{ends[0]}, write_end{ends[1]};
    fcntl(write_end.value, F_SETFL, fcntl(write_end.value, F_GETFL) | O_NONBLOCK);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, read_end.value, STDIN_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, fileno(errors.get()), STDERR_FILENO);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    char name[] = "gnuplot";
    char* arguments[] = {name, nullptr};
    const IgnoredBrokenPipe ignored;
    pid_t child = 0;
    const int spawned = posix_spawnp(&child, name, &actions, &attributes, arguments, environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    if (spawned == ENOENT) throw RenderError("gnuplot not found: install gnuplot-nox (make deps)");
    if (spawned != 0) throw RenderError(std::string("cannot run gnuplot: ") + std::strerror(spawned));
    read_end.reset();

    const auto deadline = std::chrono::steady_clock::now() + gnuplot_time_limit;
    const bool fed = feed(write_end.value, text, deadline);
    write_end.reset();
    const int status = wait_for(child, deadline);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        if (fed) return;
        throw RenderError("gnuplot stopped reading its script before the end");
    }
    const std::string message = last_line(errors.get());
    const std::string how = WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                              : "killed by signal " + std::to_string(WTERMSIG(status));
    throw RenderError("gnuplot failed (" + how + ")" + (message.empty() ? "" : ": " + message));
}

void write_png(const std::string& path, const std::function<std::string(const std::string& output)>& script_for) {
    write_atomically_by(path, [&](const std::string& temporary) {
        run(script_for(temporary));
        if (!starts_as_png(temporary)) throw RenderError("gnuplot wrote no PNG for '" + path + "'");
    });
}

}  // namespace superpack::gnuplot
