// Seeded random mutations of a certificate for the checker's fuzz test (NOTES.md 8.8): digits of
// the exact numbers, signs, keys, types, structure, truncation, deep nesting and integers beyond 64 bits. Each mutation is
// given as the text of the mutated file, since several (a duplicate key, a cut, deep nesting)
// cannot be held by a parsed document.
#pragma once
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

namespace superpack_fuzz {

using Json = nlohmann::json;

enum class MutationKind {
    mantissa_digit,  // one digit of m in "m*2^e"
    exponent_digit,  // one digit, or the sign, of e
    sign,            // negate an exact number or a JSON number
    number_digit,    // one digit of a JSON integer or of a rational "a/b"
    delete_key,
    rename_key,      // a changed spelling, or another key of the document
    duplicate_key,   // the key twice in its object, with the same or another value
    change_type,     // null, a boolean, a number, a string, an array or an object instead
    wrap,            // v -> [v] or {"value": v}
    unwrap,          // an array or object -> one of its values
    swap,            // two elements of an array
    transplant,      // a value replaced by a copy of another value of the document
    truncate,        // the file cut at a random byte
    deep_nest,       // a value inside many nested arrays (around and far beyond max_json_depth)
    integer_wrap,    // a JSON integer replaced by one a 64-bit reader would wrap or negate (issue 44)
};
constexpr int mutation_kinds = 15;
const char* to_string(MutationKind kind);

// The places of one document that each kind can act on (JSON pointers), found once.
class Sites {
public:
    explicit Sites(const Json& document);
    const std::vector<std::string>& values() const { return values_; }
    const std::vector<std::string>& dyadics() const { return dyadics_; }
    const std::vector<std::string>& exponents() const { return exponents_; }
    const std::vector<std::string>& numbers() const { return numbers_; }
    const std::vector<std::string>& members() const { return members_; }
    const std::vector<std::string>& containers() const { return containers_; }
    const std::vector<std::string>& long_arrays() const { return long_arrays_; }
    const std::vector<std::string>& keys() const { return keys_; }

private:
    std::vector<std::string> values_, dyadics_, exponents_, numbers_, members_, containers_, long_arrays_, keys_;
};

struct Mutation {
    std::string text;   // the mutated file
    std::string where;  // the JSON pointer (or byte offset) acted on, for the failure report
};

Mutation mutate(const Json& document, const Sites& sites, MutationKind kind, std::mt19937_64& random);

}  // namespace superpack_fuzz
