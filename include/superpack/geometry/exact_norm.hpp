// Exact decision of ||v||_(2p) = 2 for a vector v with rational coordinates and a rational
// p >= 1/2: the contact test of check-lattice on exact bases (NOTES.md section 5.3). For large
// 2p it decides from the structure of v where it can and bounds the size of the numbers it forms.
#pragma once
#include <array>
#include <string>

#include "superpack/arith/exact.hpp"

namespace superpack {

enum class ExactNorm { two, not_two, unknown };

struct ExactNormDecision {
    ExactNorm answer;
    std::string reason;
};

// The largest power formed (in bits of the exact integers) before the test says `unknown`.
constexpr unsigned long exact_norm_bit_budget = 1ul << 24;

ExactNormDecision decide_norm_is_two(const std::array<Rational, 3>& v, const Rational& p);

}  // namespace superpack
