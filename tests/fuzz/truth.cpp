#include "truth.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <optional>

namespace superpack_fuzz {

namespace {

bool all_digits(const std::string& text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::optional<mpz_class> integer(const std::string& text) {
    const std::size_t sign = !text.empty() && text[0] == '-' ? 1 : 0;
    if (!all_digits(text.substr(sign))) return std::nullopt;
    return mpz_class(text, 10);
}

// "m*2^e", "m" or "a/b" exactly (the exponent as the checker allows it, |e| < 10^8).
std::optional<mpq_class> exact(const std::string& text) {
    const std::size_t star = text.find("*2^"), slash = text.find('/');
    if (slash != std::string::npos) {
        const auto a = integer(text.substr(0, slash)), b = integer(text.substr(slash + 1));
        if (!a || !b || *b == 0) return std::nullopt;
        mpq_class value(*a, *b);
        value.canonicalize();
        return value;
    }
    const auto m = integer(text.substr(0, star));
    if (!m) return std::nullopt;
    mpq_class value(*m);
    if (star == std::string::npos) return value;
    const auto e = integer(text.substr(star + 3));
    if (!e || abs(*e) >= 100000000) return std::nullopt;
    const long exponent = e->get_si();
    if (exponent >= 0) mpq_mul_2exp(value.get_mpq_t(), value.get_mpq_t(), static_cast<mp_bitcnt_t>(exponent));
    else mpq_div_2exp(value.get_mpq_t(), value.get_mpq_t(), static_cast<mp_bitcnt_t>(-exponent));
    return value;
}

mpq_class power_of_ten(long n) {
    mpz_class power;
    mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(std::labs(n)));
    return n >= 0 ? mpq_class(power) : mpq_class(1, power);
}

// A decimal reference as [value - margin, value + margin]: a value printed to 30 or more
// significant digits is rounded, so its margin is 10^5 units of its last digit; a shorter one
// ("1", "1.9") is exact.
struct Reference {
    mpq_class lo, hi;
};
Reference reference(const std::string& decimal) {
    std::string mantissa = decimal;
    long exponent = 0;
    const std::size_t e = decimal.find_first_of("eE");
    if (e != std::string::npos) {
        mantissa = decimal.substr(0, e);
        exponent = std::stol(decimal.substr(e + 1));
    }
    const std::size_t point = mantissa.find('.');
    if (point != std::string::npos) {
        exponent -= static_cast<long>(mantissa.size() - point - 1);
        mantissa.erase(point, 1);
    }
    const auto digits = integer(mantissa);
    if (!digits) throw std::runtime_error("fuzz reference: not a decimal: " + decimal);
    const mpq_class value = mpq_class(*digits) * power_of_ten(exponent);
    const std::string significant = mpz_class(abs(*digits)).get_str();
    const long length = static_cast<long>(significant.size());
    const mpq_class margin = length >= 30 ? power_of_ten(exponent + 5) : mpq_class(0);
    return {value - margin, value + margin};
}

struct Interval {
    mpq_class lo, hi;
};
std::optional<Interval> interval(const Json& node) {
    if (!node.is_object() || !node.contains("lo") || !node.contains("hi") || !node["lo"].is_string() || !node["hi"].is_string())
        return std::nullopt;
    const auto lo = exact(node["lo"]), hi = exact(node["hi"]);
    if (!lo || !hi || *lo > *hi) return std::nullopt;
    return Interval{*lo, *hi};
}
bool is_interval(const Json& node) { return node.is_object() && node.contains("lo") && node.contains("hi") && node["lo"].is_string(); }
bool holds(const Interval& x, const Reference& r) { return x.lo <= r.lo && r.hi <= x.hi; }

std::vector<std::string> segments(const std::string& pointer) {
    std::vector<std::string> result;
    for (std::size_t at = 0; at < pointer.size();) {
        const std::size_t next = std::min(pointer.find('/', at + 1), pointer.size());
        result.push_back(pointer.substr(at + 1, next - at - 1));
        at = next;
    }
    return result;
}

bool matches(const std::string& pattern, const std::string& pointer) {
    const std::vector<std::string> want = segments(pattern), have = segments(pointer);
    if (want.size() != have.size()) return false;
    for (std::size_t k = 0; k < want.size(); ++k)
        if (want[k] == "*" ? !all_digits(have[k]) : want[k] != have[k]) return false;
    return true;
}

const Rule* rule_at(const std::vector<Rule>& rules, const std::string& pointer) {
    for (const Rule& rule : rules)
        if (matches(rule.pointer, pointer)) return &rule;
    return nullptr;
}

bool same_number(const Json& a, const Json& b) {
    if (a.is_number_integer() && b.is_number_integer()) {
        if (a.is_number_unsigned() != b.is_number_unsigned() && (a.get<double>() < 0 || b.get<double>() < 0)) return false;
        return a.is_number_unsigned() ? a.get<std::uint64_t>() == b.get<std::uint64_t>() : a.get<std::int64_t>() == b.get<std::int64_t>();
    }
    return a.get<double>() == b.get<double>();
}

// Keys that state nothing (NOTES.md 8.1): "decimal" beside exact endpoints is for people only,
// "p_decimal" is the user's spelling of the exact p beside it, "range_note" the producer's prose
// on an audit's "range" beside it (which is what the claim holds on).
bool informational(const std::string& key) { return key == "decimal" || key == "p_decimal" || key == "range_note"; }

class Judge {
public:
    explicit Judge(const std::vector<Rule>& rules) : rules_(rules) {}

    // Empty when `mutated` at `pointer` states nothing false about what `original` states.
    std::string judge(const Json& original, const Json& mutated, const std::string& pointer) const {
        const Rule* rule = rule_at(rules_, pointer);
        if (rule && rule->kind == Rule::Kind::covers) return covers(*rule, mutated, pointer);
        if (is_interval(original)) return enclosure(original, mutated, rule, pointer);
        if (original == mutated) return "";
        if (original.is_object()) {
            if (!mutated.is_object()) return pointer + ": an object became " + mutated.dump().substr(0, 80);
            for (const auto& [key, value] : original.items()) {
                if (informational(key)) continue;
                if (!mutated.contains(key)) return pointer + "/" + key + ": a claimed key is gone";
                const std::string failure = judge(value, mutated[key], pointer + "/" + key);
                if (!failure.empty()) return failure;
            }
            return "";
        }
        if (original.is_array()) {
            if (!mutated.is_array()) return pointer + ": an array became " + mutated.dump().substr(0, 80);
            if (original.size() == mutated.size()) {
                std::string failure;
                for (std::size_t k = 0; k < original.size() && failure.empty(); ++k)
                    failure = judge(original[k], mutated[k], pointer + "/" + std::to_string(k));
                if (failure.empty()) return "";
                // A list of lists or objects (contact vectors, basis rows) in another order states the same.
                if (std::all_of(original.begin(), original.end(), [](const Json& x) { return x.is_structured(); }) &&
                    std::is_permutation(original.begin(), original.end(), mutated.begin()))
                    return "";
                return failure;
            }
            return pointer + ": a list of " + std::to_string(original.size()) + " became one of " + std::to_string(mutated.size());
        }
        if (original.is_string() && mutated.is_string()) {
            const auto a = exact(original), b = exact(mutated);
            if (a && b && *a == *b) return "";
        }
        if (original.is_number() && mutated.is_number() && same_number(original, mutated)) return "";
        return pointer + ": " + original.dump().substr(0, 80) + " became " + mutated.dump().substr(0, 80);
    }

private:
    std::string enclosure(const Json& original, const Json& mutated, const Rule* rule, const std::string& pointer) const {
        const auto stated = interval(mutated);
        if (!stated) return pointer + ": an exact interval became " + mutated.dump().substr(0, 80);
        const Interval before = *interval(original);
        if (rule && rule->kind == Rule::Kind::within_original) {
            if (before.lo <= stated->lo && stated->hi <= before.hi) return "";
            return pointer + ": the range the claim holds on grew beyond the original";
        }
        if (rule) {
            for (const std::string& value : rule->values)
                if (!holds(*stated, reference(value))) return pointer + ": the enclosure no longer holds the reference " + value;
            return "";
        }
        if (stated->lo <= before.lo && before.hi <= stated->hi) return "";
        return pointer + ": narrower than the original, and no reference to judge it by";
    }

    std::string covers(const Rule& rule, const Json& mutated, const std::string& pointer) const {
        if (!mutated.is_array()) return pointer + ": the covering list became " + mutated.dump().substr(0, 80);
        std::vector<Interval> pieces;
        for (const Json& element : mutated) {
            const auto piece = interval(element);
            if (!piece) return pointer + ": an element is no exact interval";
            pieces.push_back(*piece);
        }
        for (const std::string& value : rule.values) {
            const Reference r = reference(value);
            if (std::none_of(pieces.begin(), pieces.end(), [&](const Interval& x) { return holds(x, r); }))
                return pointer + ": no interval of the list holds " + value;
        }
        return "";
    }

    const std::vector<Rule>& rules_;
};

}  // namespace

std::vector<Rule> rules_for(const Json& references, const std::string& file) {
    std::vector<Rule> rules;
    if (!references["certificates"].contains(file)) return rules;
    for (const Json& entry : references["certificates"][file]) {
        Rule rule;
        rule.pointer = entry["pointer"];
        if (entry.contains("contains")) rule.values = entry["contains"].get<std::vector<std::string>>();
        else if (entry.contains("covers")) {
            rule.kind = Rule::Kind::covers;
            rule.values = entry["covers"].get<std::vector<std::string>>();
        } else {
            rule.kind = Rule::Kind::within_original;
        }
        rules.push_back(rule);
    }
    return rules;
}

std::string falsehood(const Json& original, const Json& mutated, const std::vector<Rule>& rules) {
    const Judge judge(rules);
    for (const char* pointer : {"/claim/kind", "/claim/data", "/inputs"}) {
        const Json::json_pointer at(pointer);
        if (!mutated.contains(at)) return std::string(pointer) + ": gone";
        const std::string failure = judge.judge(original[at], mutated[at], pointer);
        if (!failure.empty()) return failure;
    }
    return "";
}

}  // namespace superpack_fuzz
