// One command line run to its end: the executable's main() and the Python module (python/)
// both call this, so that a command and its Python function are the same code.
#pragma once
#include <string>

namespace superpack::cli {

struct CommandOutcome {
    int code = 0;          // the exit code (ExitCode)
    std::string message;   // the error, empty when code is 0
    std::string command;   // the subcommand named, for the header of an error document
    bool json = false;     // --json was given
};

// Parses `argv` (argv[0] is the program's name), runs the subcommand and maps every exception
// to its exit code and message. Help and --version print and return 0. Never throws.
// Not reentrant: the commands print to std::cout and std::cerr.
CommandOutcome run_command_line(int argc, char** argv);

// A failed run's error as the executable reports it: one line on stderr and, with --json, one
// document on stdout unless the command printed its own. Returns the exit code.
int report_failure(const CommandOutcome& outcome);

}  // namespace superpack::cli
