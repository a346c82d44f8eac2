// Shared pieces of the subcommands: exit codes, argument parsing, backend dispatch.
// No mathematics lives in src/cli/: each subcommand parses, calls one driver, prints.
#pragma once
#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "superpack/cert/output_header.hpp"
#include "superpack/problems/family_json.hpp"

namespace superpack::cli {

enum ExitCode : int {
    exit_ok = 0,
    exit_invalid = 1,      // verify: the certificate is invalid
    exit_usage = 2,        // bad usage or input
    exit_impossible = 3,   // a certified mathematical impossibility (e.g. no root)
    exit_undecided = 4,    // the computation could not decide at this precision
};

// A failure that carries its exit code; main prints its message as one line.
struct Failure : std::runtime_error {
    int code;
    Failure(int exit_code, const std::string& message) : std::runtime_error(message), code(exit_code) {}
};

// p > 0, read exactly.
Rational parse_p(const std::string& text);
// --digits: a whole number from 1 to 100000.
long parse_digits(const std::string& text);

// Runs `body(field, digits)` with binary64 intervals when no --digits was given (digits 15)
// and with Arb balls at bits_for_digits(D) otherwise.
template <class Body>
int with_field(const std::string& digits_text, const Body& body) {
    if (digits_text.empty()) return body(DoubleField{}, 15L);
    const long digits = parse_digits(digits_text);
    return body(BallField{bits_for_digits(digits)}, digits);
}

// The rounding self-test gate: throws Failure unless directed rounding works here.
void require_rounding_self_test();

// Each subcommand file registers itself with a static SubcommandRegistration, so adding
// a subcommand touches no other file. main() adds them in name order.
using AddSubcommand = void (*)(CLI::App&);
struct SubcommandRegistration {
    SubcommandRegistration(const char* name, AddSubcommand add);
};
std::vector<std::pair<std::string, AddSubcommand>>& subcommand_registry();

}  // namespace superpack::cli
