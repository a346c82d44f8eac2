#include "checker/core/document_check.hpp"

#include "checker/core/limits.hpp"
#include "checker/core/render.hpp"

namespace superpack_checker {

namespace {

void check_decimal(Context& context, const Json& node, const std::string& path) {
    const Real x = context.interval(node, path);
    const Json& decimal = context.member(node, "decimal", path);
    if (!decimal.is_string()) context.malformed(path + ".decimal", "expected a string");
    const std::string own = decimal_field(x);
    if (decimal.get<std::string>() != own)
        context.reject(path + ".decimal", "the decimal " + decimal.get<std::string>().substr(0, 120) +
                                              " is not the checker's rendering " + own + " of the exact ends");
}

void walk(Context& context, const Json& node, const std::string& path) {
    if (node.is_array()) {
        for (std::size_t k = 0; k < node.size(); ++k) walk(context, node[k], path + "[" + std::to_string(k) + "]");
        return;
    }
    if (!node.is_object()) return;
    if (node.contains("decimal")) check_decimal(context, node, path);
    for (auto entry = node.begin(); entry != node.end(); ++entry) {
        const std::string at = path.empty() ? entry.key() : path + "." + entry.key();
        if (!context.was_read(*entry)) context.reject(at, "unknown key \"" + entry.key() + "\": no step of this claim kind reads it");
        walk(context, *entry, at);
    }
}

// The producer's description of itself: read (and typed), not checked against anything.
void read_description(Context& context, const Json& document) {
    for (const char* key : {"tool", "version", "commit", "command", "backend"}) context.string_at(document, key, "");
    read_integer(context, context.member(document, "digits", ""), "digits", 1, max_digits, "max_digits");
    const Json& checks = context.member(context.member(document, "rounding_self_test", ""), "checks", "rounding_self_test");
    read_integer(context, checks, "rounding_self_test.checks", 0, std::numeric_limits<long>::max());
}

// Up to 60 characters of `text` from `from`, marked where cut.
std::string excerpt(const std::string& text, std::size_t from) {
    const std::string cut = text.substr(from, 60);
    return std::string(from > 0 ? "..." : "") + cut + (from + 60 < text.size() ? "..." : "");
}

}  // namespace

void check_document(Context& context, const Json& document, const std::string& stated_text, const std::string& rendered_text) {
    read_description(context, document);
    walk(context, document, "");
    if (stated_text == rendered_text) return;
    std::size_t first = 0;
    while (first < stated_text.size() && first < rendered_text.size() && stated_text[first] == rendered_text[first]) ++first;
    const std::size_t from = first > 20 ? first - 20 : 0;
    context.reject("claim.text", "differs from the checker's rendering at character " + std::to_string(first) + ": stated \"" +
                                     excerpt(stated_text, from) + "\", rendered \"" + excerpt(rendered_text, from) + "\"");
}

}  // namespace superpack_checker
