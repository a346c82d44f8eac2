#include "checker/formulas/kkt_point.hpp"

namespace superpack_checker {

KktPoint replay_kkt_point(Context& context, const std::vector<Triple>& contacts, const Json& leaf, const std::string& path,
                          const Real& p) {
    context.current_step = path;
    if (!leaf.is_object()) context.malformed(path, "expected a Krawczyk leaf");
    // check_root_leaf would also accept a root-free leaf: the point needs exactly one root.
    if (context.string_at(leaf, "kind", path) != "krawczyk") context.malformed(path + ".kind", "expected \"krawczyk\"");
    if (context.string_at(leaf, "status", path) != "unique") context.malformed(path + ".status", "expected \"unique\"");
    const Box box = context.box(context.member(leaf, "box", path), path + ".box");
    const std::size_t n = 9 + contacts.size();
    context.require(box.size() == n, path + ".box",
                    "the box has " + std::to_string(box.size()) + " components, the KKT system of " +
                        std::to_string(contacts.size()) + " contact pairs has " + std::to_string(n) + " unknowns");
    const System system = kkt_system(KktEquations{contacts, p});
    std::vector<Box> roots;
    try {
        check_root_leaf(context, system, leaf, box, path, &roots);
    } catch (const UnboundedPower& error) {
        context.reject(path + ".box", std::string("a contact coordinate may be 0 on the box where 2p - 2 < 0, so the "
                                                  "Hessian of the norm, and the KKT Jacobian, have no bound there: ") +
                                          error.what());
    }
    const Box& root = roots.front();
    KktPoint point{{{{root[0], root[1], root[2]}, {root[3], root[4], root[5]}, {root[6], root[7], root[8]}}},
                   Box(root.begin() + 9, root.end()),
                   root};
    return point;
}

}  // namespace superpack_checker
