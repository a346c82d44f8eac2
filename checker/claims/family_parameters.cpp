#include "checker/claims/family_parameters.hpp"

#include "checker/formulas/kkt_point.hpp"

namespace superpack_checker {

std::string read_family(Context& context, const Json& data, const Json& inputs) {
    const std::string family = context.string_at(data, "family", "claim.data");
    context.require(context.string_at(inputs, "family", "inputs") == family, "inputs.family",
                    "the input family differs from the claim's");
    return family;
}

namespace {

System one_dimensional(const CubicEquation& equation) {
    return {[equation](const Box& x) { return std::vector<Real>{equation.value(x[0])}; },
            [equation](const Box& x) { return std::vector<std::vector<Real>>{{equation.derivative(x[0])}}; }};
}

// C0, C1: s is the unique root in the Newton box (for every p of the interval), and the
// partition of [0, lower end of that box] holds no root, so s is the smallest positive root.
FamilyParameters replay_cubic(Context& context, const Json& proof, const std::string& path, bool c1, const Real& p) {
    const CubicEquation equation{c1, p};
    if (context.string_at(proof, "kind", path) != "all") context.malformed(path + ".kind", "expected \"all\"");
    const Json& cases = context.member(proof, "cases", path);
    if (!cases.is_array()) context.malformed(path + ".cases", "expected an array");
    // A missing case is a gap in the proof (invalid), not a damaged file.
    context.require(cases.size() == 2, path + ".cases", "expected two cases: a Newton leaf and a partition");
    const std::string newton_path = path + ".cases[0]";
    const Json& newton = cases[0];
    if (context.string_at(newton, "kind", newton_path) != "newton") context.malformed(newton_path + ".kind", "expected newton");
    const Real box = context.box(context.member(newton, "box", newton_path), newton_path + ".box").at(0);
    const Real center = context.box(context.member(newton, "midpoint", newton_path), newton_path + ".midpoint").at(0);
    const Real derivative = context.box(context.member(newton, "derivative", newton_path), newton_path + ".derivative").at(0);
    const Real image = context.box(context.member(newton, "image", newton_path), newton_path + ".image").at(0);
    const Real stored_root = context.box(context.member(newton, "root", newton_path), newton_path + ".root").at(0);
    Real s = replay_newton(
        context, [&](const Real& x) { return equation.value(x); }, [&](const Real& x) { return equation.derivative(x); },
        box, center, &derivative, &image, newton_path);
    // The stored root box holds the root if the checker's does, or, when the checker's Newton
    // iterates stopped elsewhere (a p interval makes f(m) wide), if it lies in the Newton box,
    // where f' has one sign, and f changes sign across it for every p of the interval. Then
    // both boxes hold the root, and so does their intersection.
    auto sign_change = [&] {
        if (!subset(stored_root, box)) return false;
        const Real low = equation.value(lower_point(stored_root)), high = equation.value(upper_point(stored_root));
        return (negative(low) && positive(high)) || (positive(low) && negative(high));
    };
    if (!subset(s, stored_root)) {
        context.require(sign_change() && intersect(s, s, stored_root), newton_path + ".root",
                        "the stored root box " + text(stored_root) + " does not hold the root " + text(s));
    }
    context.require(positive(s), newton_path + ".root", "the root may not be positive");

    const std::string below_path = path + ".cases[1]";
    const System system = one_dimensional(equation);
    const Box covered = check_partition(context, cases[1], below_path, [&](const Json& leaf, const Box& piece, const std::string& at) {
        check_root_leaf(context, system, leaf, piece, at, nullptr);
        context.require(context.string_at(leaf, "kind", at) != "krawczyk" || context.string_at(leaf, "status", at) == "none",
                        at, "a root below the Newton box: s would not be the smallest positive root");
    });
    context.current_step = below_path;
    context.require(covered.size() == 1 && mpfr_sgn(covered[0].lo()) <= 0 && mpfr_cmp(covered[0].hi(), box.lo()) >= 0,
                    below_path + ".box", "the root-free partition does not cover [0, lower end of the Newton box]");
    const Real t = equation.shift();
    return {{{"s", s}}, {{"t", t}, {"s", s}}, c1 ? c1_basis(s, t) : c0_basis(s, t)};
}

FamilyParameters replay_o0(Context& context, const Json& proof, const std::string& path, const Real& p) {
    if (context.string_at(proof, "kind", path) != "evaluation") context.malformed(path + ".kind", "expected \"evaluation\"");
    const Real c = o0_height(p);
    return {{{"c", c}}, {{"c", c}}, o0_basis(c)};
}

// The "all roots" proof of O1 and D14: one partition case whose pieces are root leaves of
// `system`, covering `required` (a box of the unknowns, named `unknowns` and `required_words` in
// rejections), with pairwise distinct roots. Returns the certified roots.
std::vector<Box> replay_all_roots(Context& context, const Json& proof, const std::string& path, const System& system,
                                  const Box& required, const std::string& unknowns, const std::string& required_words) {
    if (context.string_at(proof, "kind", path) != "all") context.malformed(path + ".kind", "expected \"all\"");
    const Json& cases = context.member(proof, "cases", path);
    if (!cases.is_array()) context.malformed(path + ".cases", "expected an array");
    context.require(cases.size() == 1, path + ".cases", "expected one case: the partition");
    const std::string partition_path = path + ".cases[0]";
    std::vector<Box> roots;
    const Box covered = check_partition(context, cases[0], partition_path, [&](const Json& leaf, const Box& piece, const std::string& at) {
        if (piece.size() != required.size()) context.malformed(at + ".box", "expected a " + unknowns + " box");
        check_root_leaf(context, system, leaf, piece, at, &roots);
    });
    context.current_step = partition_path;
    bool covers = covered.size() == required.size();
    for (std::size_t k = 0; covers && k < required.size(); ++k) covers = subset(required[k], covered[k]);
    context.require(covers, partition_path + ".box", "the partition does not cover " + required_words);
    for (std::size_t a = 0; a < roots.size(); ++a)
        for (std::size_t b = a + 1; b < roots.size(); ++b)
            context.require(disjoint(roots[a], roots[b]), partition_path, "two pieces may hold the same root");
    return roots;
}

// O1: the pieces partition [0,1] x [-1,1], which holds every root of Eq. 12 with q >= 0; the
// roots of `unique` pieces are distinct, and (q, s) is the one with the largest s (the
// Minkowski branch, which exists for p < ln3/ln4).
FamilyParameters replay_o1(Context& context, const Json& proof, const std::string& path, const Real& p,
                           const std::string& p_path) {
    const System system = octahedral_system(p);
    const mpfr_prec_t precision = p.precision();
    const std::string partition_path = path + ".cases[0]";
    const std::vector<Box> roots =
        replay_all_roots(context, proof, path, system,
                         {hull(integer(0, precision), integer(1, precision)), hull(integer(-1, precision), integer(1, precision))},
                         "(q, s)", "[0,1] x [-1,1]");
    const Real crossover = log(integer(3, precision)) / log(integer(4, precision));
    context.require(less(p, crossover), p_path, "p is not below p*_o = ln3/ln4, where the Minkowski branch ends");
    context.require(!roots.empty(), partition_path, "no root of Eq. (12) with q >= 0");
    std::size_t largest = 0;
    for (std::size_t k = 1; k < roots.size(); ++k)
        if (middle(roots[k][1]) > middle(roots[largest][1])) largest = k;
    for (std::size_t k = 0; k < roots.size(); ++k)
        context.require(k == largest || less(roots[k][1], roots[largest][1]), partition_path,
                        "the root with the largest s is not determined");
    const Real& q = roots[largest][0];
    const Real& s = roots[largest][1];
    const Real l = OctahedralEquations{p}.l();
    return {{{"l", l}, {"q", q}, {"s", s}}, {{"l", l}, {"q", q}, {"s", s}}, o1_basis(q, s, l)};
}

// D14: the pieces partition [0,1] x [-1,1]^2, which holds every root with x >= 0 (the first
// equation bounds |x|, |y|, |z| by 1); the roots of `unique` pieces are distinct, and exactly one
// of them has x, y, z certainly > 0 and y certainly < z, every other one certainly fails one of
// these (a coordinate certainly < 0, or z certainly < y). A root with x < 0 fails x > 0, so it is
// the one root of the system on the branch.
FamilyParameters replay_d14(Context& context, const Json& proof, const std::string& path, const Real& p) {
    const System system = d14_system(p);
    const mpfr_prec_t precision = p.precision();
    const std::string partition_path = path + ".cases[0]";
    const Real unit = hull(integer(0, precision), integer(1, precision)), symmetric = hull(integer(-1, precision), integer(1, precision));
    const std::vector<Box> roots =
        replay_all_roots(context, proof, path, system, {unit, symmetric, symmetric}, "(x, y, z)", "[0,1] x [-1,1] x [-1,1]");
    std::vector<std::size_t> on_branch;
    for (std::size_t k = 0; k < roots.size(); ++k) {
        const Box& r = roots[k];
        const bool on = positive(r[0]) && positive(r[1]) && positive(r[2]) && less(r[1], r[2]);
        const bool off = negative(r[0]) || negative(r[1]) || negative(r[2]) || less(r[2], r[1]);
        context.require(on || off, partition_path, "a root is not certainly on or off the branch x, y, z > 0, y < z");
        if (on) on_branch.push_back(k);
    }
    context.require(on_branch.size() == 1, partition_path,
                    std::to_string(on_branch.size()) + " roots with x, y, z > 0 and y < z, expected exactly one");
    // Krawczyk replayed on a wide piece stops early; again from the root box (every iterate holds
    // the root) until it stops shrinking.
    Box r = roots[on_branch.front()];
    for (int round = 0; round < 16; ++round) {
        const KrawczykReplay tighter = replay_krawczyk(system, r, 80);
        if (tighter.status != ReplayStatus::unique) break;
        Width before, after;
        for (std::size_t k = 0; k < r.size(); ++k) {
            before = before + width(r[k]);
            after = after + width(tighter.root[k]);
        }
        r = tighter.root;
        if (!(after < 0.5 * before)) break;
    }
    return {{{"x", r[0]}, {"y", r[1]}, {"z", r[2]}}, {{"x", r[0]}, {"y", r[1]}, {"z", r[2]}}, d14_basis(r[0], r[1], r[2])};
}

// S6: the Krawczyk leaf proves exactly one KKT point (B, mu) of min det B subject to
// ||c_i B||_(2p) = 2 for the checker's own six triples in the stored box; B is the lattice, its
// nine entries the symbols of the lattice forms (kkt_forms).
FamilyParameters replay_s6(Context& context, const Json& proof, const std::string& path, const Real& p) {
    const KktPoint point = replay_kkt_point(context, s6_triples(), proof, path, p);
    NamedReals parameters, symbols;
    const std::vector<std::string> names = kkt_symbols();
    for (std::size_t k = 0; k < names.size(); ++k) symbols.emplace_back(names[k], point.root[k]);
    parameters = symbols;
    for (std::size_t i = 0; i < point.multipliers.size(); ++i)
        parameters.emplace_back("mu" + std::to_string(i + 1), point.multipliers[i]);
    return {parameters, symbols, point.basis};
}

}  // namespace

const std::vector<Triple>& s6_triples() {
    static const std::vector<Triple> triples{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, -1}, {1, 0, -1}, {1, -1, 0}};
    return triples;
}

void check_family_definition(Context& context, const std::string& family, const Json& data) {
    const std::string path = "claim.data.contact_pairs";
    // The other families state nothing more: an unread key is rejected by the document check.
    if (family != "S6") return;
    const Json& list = context.member(data, "contact_pairs", "claim.data");
    if (!list.is_array()) context.malformed(path, "expected an array of triples");
    const std::vector<Triple>& own = s6_triples();
    context.require(list.size() == own.size(), path,
                    "S6 has " + std::to_string(own.size()) + " contact pairs, the claim lists " + std::to_string(list.size()));
    for (std::size_t k = 0; k < own.size(); ++k) {
        const std::string at = path + "[" + std::to_string(k) + "]";
        context.require(read_triple(context, list[k], at) == own[k], at,
                        "not S6's contact triple " + triple_text(own[k]) + " (NOTES.md 4.2)");
    }
}

FamilyForms lattice_forms(const std::string& family) {
    return family == "S6" ? kkt_forms(s6_triples()) : family_forms(family);
}

System d14_system(const Real& p) {
    const D14Equations equations{p};
    return {[equations](const Box& v) {
                const auto values = equations.value({v[0], v[1], v[2]});
                return std::vector<Real>(values.begin(), values.end());
            },
            [equations](const Box& v) {
                const auto j = equations.jacobian({v[0], v[1], v[2]});
                std::vector<std::vector<Real>> rows;
                for (const auto& row : j) rows.emplace_back(row.begin(), row.end());
                return rows;
            }};
}

System octahedral_system(const Real& p) {
    const OctahedralEquations equations{p};
    return {[equations](const Box& x) {
                const auto values = equations.value({x[0], x[1]});
                return std::vector<Real>{values[0], values[1]};
            },
            [equations](const Box& x) {
                const auto j = equations.jacobian({x[0], x[1]});
                return std::vector<std::vector<Real>>{{j[0][0], j[0][1]}, {j[1][0], j[1][1]}};
            }};
}

namespace {

// The checker's side of the family registry: one entry per family, with its claimed domain
// (a check of [lo, hi] that rejects at `path`) and the replay of its parameter proof. A family
// unknown here is malformed wherever a claim names it.
struct CheckerFamily {
    const char* name;
    void (*require_domain)(Context& context, const mpq_class& lo, const mpq_class& hi, const std::string& path);
    FamilyParameters (*replay)(Context& context, const Json& proof, const std::string& path, const Real& p,
                               const std::string& p_path);
};

void require_s6_domain(Context& context, const mpq_class& lo, const mpq_class& hi, const std::string& path) {
    context.require(hi < 1, path, "outside the domain ln3/ln4 < p < 1 of S6: p is not below 1");
    const mpfr_prec_t precision = context.precision();
    const Real crossover = log(integer(3, precision)) / log(integer(4, precision));
    context.require(less(crossover, rational(lo, precision)), path,
                    "outside the domain ln3/ln4 < p < 1 of S6: p is not certainly above ln3/ln4");
}

const std::vector<CheckerFamily>& checker_families() {
    using Path = const std::string&;
    static const std::vector<CheckerFamily> families{
        {"C0", [](Context& c, const mpq_class& lo, const mpq_class&, Path path) { c.require(lo >= 1, path, "outside the domain p >= 1 of C0"); },
         [](Context& c, const Json& proof, Path path, const Real& p, Path) { return replay_cubic(c, proof, path, false, p); }},
        {"C1", [](Context& c, const mpq_class& lo, const mpq_class&, Path path) { c.require(lo >= 1, path, "outside the domain p >= 1 of C1"); },
         [](Context& c, const Json& proof, Path path, const Real& p, Path) { return replay_cubic(c, proof, path, true, p); }},
        {"O0",
         [](Context& c, const mpq_class& lo, const mpq_class& hi, Path path) {
             c.require(lo > mpq_class(1, 2) && hi <= 1, path, "outside the domain 1/2 < p <= 1 of O0");
         },
         [](Context& c, const Json& proof, Path path, const Real& p, Path) { return replay_o0(c, proof, path, p); }},
        {"O1",
         [](Context& c, const mpq_class& lo, const mpq_class&, Path path) {
             c.require(lo >= mpq_class(1, 2), path, "outside the domain p >= 1/2 of O1");
         },
         replay_o1},
        {"D14",
         [](Context& c, const mpq_class& lo, const mpq_class& hi, Path path) {
             c.require(lo >= mpq_class(1, 2) && hi <= 1, path, "outside the domain 1/2 <= p <= 1 of D14");
         },
         [](Context& c, const Json& proof, Path path, const Real& p, Path) { return replay_d14(c, proof, path, p); }},
        {"S6", require_s6_domain,
         [](Context& c, const Json& proof, Path path, const Real& p, Path) { return replay_s6(c, proof, path, p); }},
    };
    return families;
}

const CheckerFamily& checker_family(Context& context, const std::string& family) {
    for (const CheckerFamily& entry : checker_families())
        if (family == entry.name) return entry;
    context.malformed("claim.data.family", "unknown family \"" + family + "\"");
}

}  // namespace

void require_family_domain(Context& context, const std::string& family, const mpq_class& lo, const mpq_class& hi,
                           const std::string& path) {
    checker_family(context, family).require_domain(context, lo, hi, path);
}

FamilyParameters replay_family_parameters(Context& context, const std::string& family, const Json& proof,
                                          const std::string& path, const Real& p, const std::string& p_path) {
    return checker_family(context, family).replay(context, proof, path, p, p_path);
}

}  // namespace superpack_checker
