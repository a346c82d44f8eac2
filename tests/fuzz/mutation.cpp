#include "mutation.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <set>

#include "checker/core/limits.hpp"

namespace superpack_fuzz {

const char* to_string(MutationKind kind) {
    switch (kind) {
        case MutationKind::mantissa_digit: return "mantissa_digit";
        case MutationKind::exponent_digit: return "exponent_digit";
        case MutationKind::sign: return "sign";
        case MutationKind::number_digit: return "number_digit";
        case MutationKind::delete_key: return "delete_key";
        case MutationKind::rename_key: return "rename_key";
        case MutationKind::duplicate_key: return "duplicate_key";
        case MutationKind::change_type: return "change_type";
        case MutationKind::wrap: return "wrap";
        case MutationKind::unwrap: return "unwrap";
        case MutationKind::swap: return "swap";
        case MutationKind::transplant: return "transplant";
        case MutationKind::truncate: return "truncate";
        case MutationKind::deep_nest: return "deep_nest";
        case MutationKind::integer_wrap: return "integer_wrap";
    }
    return "?";
}

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool has_digit(const std::string& text) { return std::any_of(text.begin(), text.end(), is_digit); }

// "m*2^e", "m" or "a/b": strings the checker reads as exact numbers.
bool exact_number(const std::string& text) {
    if (text.empty() || text.size() > 200000 || !has_digit(text)) return false;
    return std::all_of(text.begin(), text.end(), [](char c) { return is_digit(c) || c == '-' || c == '*' || c == '^' || c == '/'; });
}

std::string escaped(const std::string& key) {
    std::string result;
    for (char c : key) {
        if (c == '~') result += "~0";
        else if (c == '/') result += "~1";
        else result += c;
    }
    return result;
}

void collect(const Json& node, const std::string& pointer, std::vector<std::string>& values, std::vector<std::string>& dyadics,
             std::vector<std::string>& exponents, std::vector<std::string>& numbers, std::vector<std::string>& members,
             std::vector<std::string>& containers, std::vector<std::string>& long_arrays, std::set<std::string>& keys) {
    values.push_back(pointer);
    if (node.is_string()) {
        const std::string& text = node.get_ref<const std::string&>();
        if (exact_number(text)) {
            (text.find('/') == std::string::npos ? dyadics : numbers).push_back(pointer);
            if (text.find("*2^") != std::string::npos) exponents.push_back(pointer);
        }
    } else if (node.is_number()) {
        numbers.push_back(pointer);
    } else if (node.is_object()) {
        if (!node.empty()) containers.push_back(pointer);
        for (const auto& [key, value] : node.items()) {
            keys.insert(key);
            members.push_back(pointer + "/" + escaped(key));
            collect(value, pointer + "/" + escaped(key), values, dyadics, exponents, numbers, members, containers, long_arrays, keys);
        }
    } else if (node.is_array()) {
        if (!node.empty()) containers.push_back(pointer);
        if (node.size() >= 2) long_arrays.push_back(pointer);
        for (std::size_t k = 0; k < node.size(); ++k)
            collect(node[k], pointer + "/" + std::to_string(k), values, dyadics, exponents, numbers, members, containers,
                    long_arrays, keys);
    }
}

template <class T>
const T& pick(const std::vector<T>& items, std::mt19937_64& random) {
    return items[std::uniform_int_distribution<std::size_t>(0, items.size() - 1)(random)];
}

std::size_t below(std::size_t n, std::mt19937_64& random) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random); }

// What a reader without a range check would wrap or negate: a negative value plus 2^64 (-1 read
// back as 2^64 - 1), 2^63 (read as -2^63), -2^63 (whose negation is undefined) or 2^64 - 1.
Json wrapped_integer(const Json& value, std::mt19937_64& random) {
    switch (below(4, random)) {
        case 0:
            if (!value.is_number_unsigned() && value.get<std::int64_t>() < 0)
                return Json(static_cast<std::uint64_t>(value.get<std::int64_t>()));
            return Json(Json::number_unsigned_t{1} << 63);
        case 1: return Json(Json::number_unsigned_t{1} << 63);
        case 2: return Json(std::numeric_limits<std::int64_t>::min());
        default: return Json(std::numeric_limits<std::uint64_t>::max());
    }
}

// A different digit at one of the digit positions in [from, to) of `text`.
std::string changed_digit(std::string text, std::size_t from, std::size_t to, std::mt19937_64& random) {
    std::vector<std::size_t> positions;
    for (std::size_t k = from; k < to && k < text.size(); ++k)
        if (is_digit(text[k])) positions.push_back(k);
    if (positions.empty()) return text + "0";
    const std::size_t at = pick(positions, random);
    const char old = text[at];
    char digit = old;
    while (digit == old) digit = static_cast<char>('0' + below(10, random));
    text[at] = digit;
    return text;
}

std::string negated(const std::string& text) { return text[0] == '-' ? text.substr(1) : "-" + text; }

// Splits a pointer into its parent and last key.
std::pair<Json::json_pointer, std::string> parent_and_key(const std::string& pointer) {
    const Json::json_pointer path(pointer);
    return {path.parent_pointer(), path.back()};
}

Json other_type(const Json& value, std::mt19937_64& random) {
    const std::vector<Json> candidates{nullptr, true, false, 0, -1, Json::number_unsigned_t(18446744073709551615ULL), 1.5,
                                       1e308, "", "x", "1", "0*2^0", Json::array(), Json::object(),
                                       Json::array({value}), value.dump()};
    Json choice = value;
    while (choice.type() == value.type() && choice == value) choice = pick(candidates, random);
    return choice;
}

// The text of `document` with the value at `pointer` written as `replacement` (any text).
std::string spliced(Json document, const std::string& pointer, const std::string& replacement) {
    const std::string marker = "@@superpack-fuzz-splice@@";
    document[Json::json_pointer(pointer)] = marker;
    std::string text = document.dump();
    const std::size_t at = text.find("\"" + marker + "\"");
    return text.substr(0, at) + replacement + text.substr(at + marker.size() + 2);
}

std::size_t nesting_depth(std::mt19937_64& random) {
    const std::size_t limit = superpack_checker::max_json_depth;
    switch (below(3, random)) {
        case 0: return 1 + below(8, random);
        case 1: return limit - 8 + below(16, random);  // around the limit (the value itself is deeper)
        default: return limit * (2 + below(200, random));
    }
}

}  // namespace

Sites::Sites(const Json& document) {
    std::set<std::string> keys;
    collect(document, "", values_, dyadics_, exponents_, numbers_, members_, containers_, long_arrays_, keys);
    values_.erase(values_.begin());  // not the document itself: a replaced document is trivially rejected
    keys_.assign(keys.begin(), keys.end());
}

Mutation mutate(const Json& document, const Sites& sites, MutationKind kind, std::mt19937_64& random) {
    Json copy = document;
    auto at = [&](const std::string& pointer) -> Json& { return copy[Json::json_pointer(pointer)]; };
    switch (kind) {
        case MutationKind::mantissa_digit: {
            if (sites.dyadics().empty()) break;
            const std::string& pointer = pick(sites.dyadics(), random);
            const std::string text = at(pointer);
            at(pointer) = changed_digit(text, 0, text.find('*'), random);
            return {copy.dump(), pointer};
        }
        case MutationKind::exponent_digit: {
            if (sites.exponents().empty()) break;
            const std::string& pointer = pick(sites.exponents(), random);
            std::string text = at(pointer);
            const std::size_t exponent = text.find("*2^") + 3;
            if (below(4, random) == 0)
                text = text.substr(0, exponent) + negated(text.substr(exponent));
            else
                text = changed_digit(text, exponent, text.size(), random);
            at(pointer) = text;
            return {copy.dump(), pointer};
        }
        case MutationKind::sign: {
            if (sites.dyadics().empty() || sites.numbers().empty()) break;
            const bool string = below(2, random) == 0;
            const std::string& pointer = pick(string ? sites.dyadics() : sites.numbers(), random);
            Json& value = at(pointer);
            if (value.is_string()) value = negated(value.get<std::string>());
            else if (value.is_number_unsigned()) value = -static_cast<Json::number_integer_t>(value.get<Json::number_unsigned_t>());
            else if (value.is_number_integer()) value = -value.get<Json::number_integer_t>();
            else value = -value.get<double>();
            return {copy.dump(), pointer};
        }
        case MutationKind::number_digit: {
            if (sites.numbers().empty()) break;
            const std::string& pointer = pick(sites.numbers(), random);
            Json& value = at(pointer);
            if (value.is_string()) {
                value = changed_digit(value.get<std::string>(), 0, std::string::npos, random);
                return {copy.dump(), pointer};
            }
            // A JSON number: a digit of its text, spliced back as text.
            return {spliced(copy, pointer, changed_digit(value.dump(), 0, std::string::npos, random)), pointer};
        }
        case MutationKind::delete_key: {
            const std::string& pointer = pick(sites.members(), random);
            const auto [parent, key] = parent_and_key(pointer);
            copy[parent].erase(key);
            return {copy.dump(), pointer};
        }
        case MutationKind::rename_key: {
            const std::string& pointer = pick(sites.members(), random);
            const auto [parent, key] = parent_and_key(pointer);
            std::string name = below(2, random) == 0 ? pick(sites.keys(), random) : key;
            if (name == key) name = key.empty() ? "x" : key.substr(0, key.size() - 1) + static_cast<char>('a' + below(26, random));
            if (name == key) name += "_";
            Json value = copy[parent][key];
            copy[parent].erase(key);
            copy[parent][name] = std::move(value);
            return {copy.dump(), pointer + " -> " + name};
        }
        case MutationKind::duplicate_key: {
            const std::string& pointer = pick(sites.members(), random);
            const auto [parent, key] = parent_and_key(pointer);
            const std::string marker = "@@superpack-fuzz-duplicate@@";
            copy[parent][marker] = below(2, random) == 0 ? copy[parent][key] : document[Json::json_pointer(pick(sites.values(), random))];
            std::string text = copy.dump();
            const std::size_t where = text.find("\"" + marker + "\"");
            text.replace(where, marker.size() + 2, Json(key).dump());
            return {text, pointer};
        }
        case MutationKind::change_type: {
            const std::string& pointer = pick(sites.values(), random);
            at(pointer) = other_type(at(pointer), random);
            return {copy.dump(), pointer};
        }
        case MutationKind::wrap: {
            const std::string& pointer = pick(sites.values(), random);
            Json value = at(pointer);
            at(pointer) = below(2, random) == 0 ? Json::array({value}) : Json{{"value", value}};
            return {copy.dump(), pointer};
        }
        case MutationKind::unwrap: {
            const std::string& pointer = pick(sites.containers(), random);
            const Json& value = at(pointer);
            auto element = value.begin();
            std::advance(element, static_cast<long>(below(value.size(), random)));
            const Json inner = *element;
            at(pointer) = inner;
            return {copy.dump(), pointer};
        }
        case MutationKind::swap: {
            if (sites.long_arrays().empty()) break;
            const std::string& pointer = pick(sites.long_arrays(), random);
            Json& array = at(pointer);
            const std::size_t i = below(array.size(), random);
            std::size_t j = below(array.size() - 1, random);
            if (j >= i) ++j;
            std::swap(array[i], array[j]);
            return {copy.dump(), pointer + " [" + std::to_string(i) + "<->" + std::to_string(j) + "]"};
        }
        case MutationKind::transplant: {
            const std::string& pointer = pick(sites.values(), random);
            const std::string& source = pick(sites.values(), random);
            at(pointer) = document[Json::json_pointer(source)];
            return {copy.dump(), pointer + " <- " + source};
        }
        case MutationKind::truncate: {
            const std::string text = document.dump(below(2, random) == 0 ? -1 : 1);
            const std::size_t cut = below(text.size(), random);
            return {text.substr(0, cut), "byte " + std::to_string(cut)};
        }
        case MutationKind::deep_nest: {
            const std::string& pointer = pick(sites.values(), random);
            const std::size_t depth = nesting_depth(random);
            return {spliced(copy, pointer, std::string(depth, '[') + at(pointer).dump() + std::string(depth, ']')),
                    pointer + " in " + std::to_string(depth) + " arrays"};
        }
        case MutationKind::integer_wrap: {
            std::vector<std::string> integers;
            for (const std::string& pointer : sites.numbers())
                if (document[Json::json_pointer(pointer)].is_number_integer()) integers.push_back(pointer);
            if (integers.empty()) break;
            const std::string& pointer = pick(integers, random);
            at(pointer) = wrapped_integer(at(pointer), random);
            return {copy.dump(), pointer};
        }
    }
    // The kind has no site in this document: an unchanged text (accepted, and judged as such).
    return {document.dump(), "(no site)"};
}

}  // namespace superpack_fuzz
