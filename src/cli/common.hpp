// Shared pieces of the subcommands: exit codes, argument parsing, backend dispatch.
// No mathematics lives in src/cli/: each subcommand parses, calls one driver, prints.
#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "superpack/arith/contract.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/cert/certificate.hpp"
#include "superpack/cert/output_header.hpp"
#include "superpack/problems/families/family_json.hpp"

namespace superpack::cli {

enum ExitCode : int {
    exit_ok = 0,
    exit_invalid = 1,      // verify: the certificate is invalid
    exit_usage = 2,        // bad usage or input
    exit_impossible = 3,   // a certified mathematical impossibility (e.g. no root)
    exit_undecided = 4,    // the computation could not decide at this precision
    exit_internal = 5,     // a bug in superpack (an exception no input should cause)
};

// A failure that carries its exit code; main prints its message as one line.
struct Failure : std::runtime_error {
    int code;
    Failure(int exit_code, const std::string& message) : std::runtime_error(message), code(exit_code) {}
};

// Limits of every command (README, "The command line"). The numerics are supported for p in
// [10^-6, 10^6]; a number is typed in at most 100 characters; an error line is cut to 300.
inline const char* const supported_p_text = "10^-6 <= p <= 10^6";
constexpr std::size_t max_number_characters = 100;
constexpr std::size_t max_error_characters = 300;

// An exact number typed for `option` (at most max_number_characters).
Rational parse_number(const std::string& text, const std::string& option);
// p for `option`: exact, within the supported range.
Rational parse_p(const std::string& text, const std::string& option = "--p");
// --scan a:b:h: the exact values a, a + h, ... <= b, at most `max_values` of them.
std::vector<Rational> parse_scan(const std::string& text, std::size_t max_values);
// --digits: a whole number from 1 to `maximum` (each command states its own).
long parse_digits(const std::string& text, long maximum);
// Adds --digits, held as typed in `digits` (with_field reads it; empty: not given), refused when
// parsed unless parse_digits takes it: an empty --digits is no request for binary64.
void add_digits_option(CLI::App& command, std::string& digits, long maximum);

// The one seed range of every command (best, simulate, md): 0 to 2^32 - 1, what best's search
// takes; a seed is typed as a whole number, so "-1" or "1e26" is refused, never wrapped.
inline const char* const seed_range_text = "0 to 4294967295 (2^32 - 1)";
std::uint32_t parse_seed(const std::string& text);
// Adds --seed, parsed by parse_seed into `seed`; `help` says what it seeds.
void add_seed_option(CLI::App& command, std::uint32_t& seed, const std::string& help);

// The message of an answer left undecided because a function's contract refused an
// enclosure (too wide at this precision), with the precision to try next
// (digits 0: binary64; maximum_digits 0: the command has no --digits).
std::string undecided_at_precision(const std::string& what, long digits, long maximum_digits);

// A driver's answer, computed through within_contract: its value when the contracts held, else
// the undecided exit (4) with the refusal's words. Every driver call of a command goes through
// it (or write_certificate_or_fail), so that a refusal on a legal input reaches the command as
// a value, never as an exception.
// `digits` is what with_field gives its body: with binary64 intervals (DoubleField) that is 15,
// but the message names binary64 and suggests --digits 30, as for digits 0.
template <class T, class Field>
T decided(Contracted<T> answer, const Field&, long digits, long maximum_digits) {
    const long given_digits = std::is_same<Field, DoubleField>::value ? 0 : digits;
    if (answer.status == ContractStatus::too_wide)
        throw Failure(exit_undecided, undecided_at_precision(answer.refusal, given_digits, maximum_digits));
    return std::move(*answer.value);
}

// decided() of a driver call in a command that computes in binary64 only (no --digits: critical,
// simulate, md): the refusal's message names binary64 and suggests no precision.
template <class Compute>
auto decided_in_binary64(const Compute& compute) {
    return decided(within_contract(compute), DoubleField{}, 0, 0);
}

// Builds and writes a certificate. A builder that refuses its candidate or a failed write is a
// usage error with the reason (never an internal one); a contract's refusal while building is
// undecided, as in decided().
template <class Field>
void write_certificate_or_fail(const std::string& path, const Field& field, long digits, long maximum_digits,
                               const std::function<Json()>& build) {
    Contracted<bool> written;
    try {
        written = within_contract([&] {
            write_certificate(path, build());
            return true;
        });
    } catch (const std::runtime_error& error) {
        throw Failure(exit_usage, std::string("no certificate written: ") + error.what());
    }
    decided(std::move(written), field, digits, maximum_digits);
}

// Runs `body(field, digits)` with binary64 intervals when no --digits was given (digits 15)
// and with Arb balls at bits_for_digits(D) otherwise.
template <class Body>
int with_field(const std::string& digits_text, long maximum_digits, const Body& body) {
    const long digits = digits_text.empty() ? 0 : parse_digits(digits_text, maximum_digits);
    if (digits == 0) return body(DoubleField{}, 15L);
    return body(BallField{bits_for_digits(digits)}, digits);
}

// An enclosure as two CSV fields "lo,hi" (lo rounded down, hi up) to `digits` digits.
template <class I>
std::string csv_enclosure(const I& x, int digits) {
    const DecimalEnclosure text = to_decimal(x, digits);
    return text.lo + "," + text.hi;
}

// Digits of a table entry: what --digits asked for, or 17 (enough for binary64) without it.
inline int table_digits(long digits, bool arb) { return arb ? static_cast<int>(digits) : 17; }

// The one JSON document of a command on stdout. main prints an error document instead
// only when no document was printed.
void print_json(const Json& document);
bool json_printed();
// At the start of a command line, so that a second run in one process (python/) starts afresh.
void forget_printed_json();

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
