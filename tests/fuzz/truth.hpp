// Is a mutated certificate that the checker accepted still a true claim? Judged without the
// checker, against the original certificate (a valid one, whose values the regular tests compare
// with mpmath) and against independent references: tests/data/fuzz_reference.json, written by
// scripts/make_fuzz_reference.py with mpmath at 50 digits (NOTES.md 8.8).
//
// What is judged: claim.kind, claim.data and inputs (claim.text is the producer's prose; the
// checker states the claim in its own words). Each exact interval [lo, hi] there is one of
//   - an enclosure of a value: the mutated interval must contain the reference values listed
//     for it ("contains"), or else contain the original interval;
//   - a range the claim holds on (a piece of p, "within_original"): it must lie in the original;
//   - one of a list of intervals that must cover given values ("covers", e.g. every minimiser).
// Everything else (names, verdicts, rationals, integers, vectors) must state the same as the
// original: equal, as numbers where both are numbers, up to order in a list of lists.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace superpack_fuzz {

using Json = nlohmann::json;

struct Rule {
    enum class Kind { contains, covers, within_original };
    std::string pointer;  // a JSON pointer; "*" stands for any array index
    Kind kind = Kind::contains;
    std::vector<std::string> values;  // decimals
};

// The rules for one certificate of proofs/ (by file name), from the reference document.
std::vector<Rule> rules_for(const Json& references, const std::string& file);

// Empty when `mutated` states only what is true, else the first falsehood (or unjudgeable change).
std::string falsehood(const Json& original, const Json& mutated, const std::vector<Rule>& rules);

}  // namespace superpack_fuzz
