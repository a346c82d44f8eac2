#include "checker/triple.hpp"

namespace superpack_checker {

std::string triple_text(const Triple& t) {
    return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

Triple read_triple(Context& context, const Json& node, const std::string& path) {
    if (!node.is_array() || node.size() != 3) context.malformed(path, "expected three integers");
    Triple t;
    for (int k = 0; k < 3; ++k) {
        if (!node[k].is_number_integer()) context.malformed(path, "expected three integers");
        t[k] = node[k].get<long>();
    }
    return t;
}

bool canonical(const Triple& t) {
    for (long x : t)
        if (x != 0) return x > 0;
    return false;
}

}  // namespace superpack_checker
