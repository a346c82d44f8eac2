// Exact inputs: p and lattice entries are rationals read from decimal strings or fractions,
// never from double literals, so that the number a proof is about is the number the user typed.
#pragma once
#include <gmpxx.h>
#include <stdexcept>
#include <string>

namespace superpack {

using Rational = mpq_class;

// Malformed or out-of-domain user input. The CLI maps it to exit code 2.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Parses "1.15", "-0.5", "2e-3", "3/2" or "7" exactly. Throws InputError naming the text otherwise.
Rational parse_rational(const std::string& text);

// "3/2" or "7": the canonical exact form used in certificates.
std::string rational_text(const Rational& value);

// The user's spelling when it was a terminating decimal, else the fraction ("0.55", "1/3").
std::string decimal_or_fraction_text(const Rational& value);

}  // namespace superpack
