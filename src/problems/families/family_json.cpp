#include "superpack/problems/families/family_json.hpp"

namespace superpack {

namespace {
const char* status_text(Outcome status) {
    switch (status) {
        case Outcome::proved: return "certified";
        case Outcome::refuted: return "no_lattice";
        case Outcome::undecided: return "undecided";
    }
    return "undecided";
}
}  // namespace

template <class I>
Json root_leaf_json(const RootLeaf<I>& leaf) {
    Json piece = Json::array(), root = Json::array();
    for (const I& x : leaf.piece) piece.push_back(enclosure_json(x));
    for (const I& x : leaf.root) root.push_back(enclosure_json(x));
    Json result{{"status", to_string(leaf.status)}, {"box", piece}, {"reason", leaf.reason}};
    if (!leaf.root.empty()) result["root"] = root;
    return result;
}

template <class I>
Json family_json(const FamilyLattice<I>& lattice) {
    Json result{{"family", to_string(lattice.family)}, {"status", status_text(lattice.status)}};
    if (!lattice.message.empty()) result["message"] = lattice.message;
    if (lattice.volume) result["volume"] = enclosure_json(*lattice.volume);
    Json parameters = Json::object();
    for (const auto& parameter : lattice.parameters) parameters[parameter.name] = enclosure_json(parameter.value);
    result["parameters"] = parameters;
    if (lattice.basis) {
        Json basis = Json::array();
        for (const auto& row : *lattice.basis) {
            Json vector = Json::array();
            for (const I& x : row) vector.push_back(enclosure_json(x));
            basis.push_back(vector);
        }
        result["basis"] = basis;
        result["determinant"] = enclosure_json(*lattice.determinant);
        result["phi"] = enclosure_json(*lattice.phi);
    }
    Json roots = Json::array();
    for (const auto& branch : lattice.branches) {
        Json unknowns = Json::object();
        for (const auto& unknown : branch.unknowns) unknowns[unknown.name] = enclosure_json(unknown.value);
        roots.push_back(Json{{"unknowns", unknowns}, {"proof", root_leaf_json(branch.proof)}});
    }
    result["roots"] = roots;
    std::size_t counts[3] = {0, 0, 0};
    for (const auto& leaf : lattice.search) ++counts[static_cast<int>(leaf.status)];
    result["search"] = Json{{"pieces", lattice.search.size()}, {"unique", counts[0]}, {"none", counts[1]},
                            {"undecided", counts[2]}};
    return result;
}

template Json family_json(const FamilyLattice<DInterval>&);
template Json family_json(const FamilyLattice<Ball>&);
template Json root_leaf_json(const RootLeaf<DInterval>&);
template Json root_leaf_json(const RootLeaf<Ball>&);

}  // namespace superpack
