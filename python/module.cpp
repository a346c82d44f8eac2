// superpack._superpack: runs one of superpack's command lines in this process with --json and
// returns its exit code and JSON document. The package (superpack/__init__.py) builds the typed
// results from that document, so that a Python function and its command are the same code and
// print the same numbers.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <exception>
#include <iostream>
#include <mutex>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "cli/command_line.hpp"

namespace py = pybind11;

namespace {

// The commands write progress lines on std::cerr: each whole line goes to the Python callback
// (under the GIL). An exception the callback raises is kept, the rest of the lines dropped,
// and it is raised again when the command has ended.
class ProgressLines : public std::streambuf {
public:
    explicit ProgressLines(py::object callback) : callback_(std::move(callback)) {}

    void flush_line() {
        if (line_.empty()) return;
        if (!callback_.is_none() && !error_) {
            py::gil_scoped_acquire acquire;
            try {
                callback_(line_);
            } catch (py::error_already_set&) {
                error_ = std::current_exception();
            }
        }
        line_.clear();
    }

    void raise_if_failed() const {
        if (error_) std::rethrow_exception(error_);
    }

protected:
    int_type overflow(int_type character) override {
        if (traits_type::eq_int_type(character, traits_type::eof())) return traits_type::not_eof(character);
        if (character == '\n')
            flush_line();
        else
            line_.push_back(traits_type::to_char_type(character));
        return character;
    }

private:
    py::object callback_;
    std::string line_;
    std::exception_ptr error_;
};

// std::cout and std::cerr belong to the process: one command at a time, whatever the thread.
std::mutex command_mutex;

// Swaps a stream's buffer for the lifetime of the object.
class StreamRedirect {
public:
    StreamRedirect(std::ostream& stream, std::streambuf* buffer) : stream_(stream), saved_(stream.rdbuf(buffer)) {}
    ~StreamRedirect() { stream_.rdbuf(saved_); }
    StreamRedirect(const StreamRedirect&) = delete;
    StreamRedirect& operator=(const StreamRedirect&) = delete;

private:
    std::ostream& stream_;
    std::streambuf* saved_;
};

// (exit code, stdout, error message): stdout holds the command's JSON document when it printed one.
py::tuple run(const std::vector<std::string>& arguments, py::object progress) {
    std::vector<std::string> words{"superpack"};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    std::ostringstream out;
    ProgressLines lines(std::move(progress));
    superpack::cli::CommandOutcome outcome;
    {
        // The GIL is released first, so that a thread waiting here never holds it.
        py::gil_scoped_release release;
        std::lock_guard<std::mutex> lock(command_mutex);
        StreamRedirect out_redirect(std::cout, out.rdbuf());
        StreamRedirect err_redirect(std::cerr, &lines);
        outcome = superpack::cli::run_command_line(static_cast<int>(words.size()), argv.data());
        std::cerr.flush();
        lines.flush_line();
    }
    lines.raise_if_failed();
    return py::make_tuple(outcome.code, out.str(), outcome.message);
}

}  // namespace

PYBIND11_MODULE(_superpack, module) {
    module.doc() = "superpack's commands run in this process (use the package superpack, not this module)";
    module.def("run", &run, py::arg("arguments"), py::arg("progress") = py::none(),
               "Runs `superpack ARGUMENTS`; returns (exit code, stdout, error message).");
}
