#include "checker/formulas/triple.hpp"

#include <set>

#include "checker/core/limits.hpp"

namespace superpack_checker {

std::string triple_text(const Triple& t) {
    return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

Triple read_triple(Context& context, const Json& node, const std::string& path) {
    if (!node.is_array() || node.size() != 3) context.malformed(path, "expected three integers");
    Triple t;
    for (int k = 0; k < 3; ++k)
        t[k] = read_integer(context, node[k], path + "[" + std::to_string(k) + "]", -max_coefficient, max_coefficient,
                            "max_coefficient");
    return t;
}

bool canonical(const Triple& t) {
    for (long x : t)
        if (x != 0) return x > 0;
    return false;
}

Triple representative(const Triple& t) { return canonical(t) ? t : Triple{-t[0], -t[1], -t[2]}; }

std::vector<Triple> read_contact_pairs(Context& context, const Json& node, const std::string& key, const std::string& path) {
    const std::string at = path + "." + key;
    const Json& list = context.member(node, key, path);
    if (!list.is_array() || list.empty() || list.size() > max_contact_pairs)
        context.malformed(at, "expected from 1 to " + std::to_string(max_contact_pairs) + " contact triples (max_contact_pairs)");
    std::vector<Triple> contacts;
    std::set<Triple> seen;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const std::string entry = at + "[" + std::to_string(k) + "]";
        const Triple t = read_triple(context, list[k], entry);
        context.require(canonical(t), entry, "not the triple of its +-pair whose first nonzero coefficient is positive");
        context.require(seen.insert(t).second, entry, "a contact pair listed twice");
        contacts.push_back(t);
    }
    return contacts;
}

}  // namespace superpack_checker
