// Claim kind "family-lattice" (written by `superpack density --certificate`): the density
// phi = V_sb(p) / |det B| of one family of Jiao, Stillinger and Torquato (2009) at an exact p.
//   C0, C1: s is the smallest positive root of Eq. 2 / Eq. 9: a Newton leaf and a root-free
//           partition of [0, lower end of the Newton box];
//   O0:     a direct evaluation (nothing to solve);
//   O1:     a partition of [0,1] x [-1,1] (all roots of Eq. 12 with q >= 0) into root-free
//           and one-root pieces; (q, s) is the root with the largest s, and p < ln3/ln4.
// The checker recomputes s (or q, s), the basis, the volume and phi in its own arithmetic
// and checks that each stated enclosure contains its own.
#include "checker/equations.hpp"
#include "checker/replay.hpp"

namespace superpack_checker {

namespace {

void check_quantities(Context& context, const Json& data, const Matrix3& basis, const Real& p,
                      const std::vector<std::pair<std::string, Real>>& parameters) {
    const Json& stated = context.member(data, "parameters", "claim.data");
    context.require(stated.is_object() && stated.size() == parameters.size(), "claim.data.parameters",
                    "unexpected parameters for this family");
    for (const auto& [name, own] : parameters)
        check_encloses(context, context.member(stated, name, "claim.data.parameters"), "claim.data.parameters." + name, own);
    const Real volume = superball_volume(p);
    const Real det = determinant(basis);
    context.require(excludes_zero(det), "claim.data.determinant", "the basis may be singular");
    check_encloses(context, context.member(data, "volume", "claim.data"), "claim.data.volume", volume);
    check_encloses(context, context.member(data, "determinant", "claim.data"), "claim.data.determinant", det);
    check_encloses(context, context.member(data, "phi", "claim.data"), "claim.data.phi", volume / abs(det));
}

System one_dimensional(const CubicEquation& equation) {
    return {[equation](const Box& x) { return std::vector<Real>{equation.value(x[0])}; },
            [equation](const Box& x) { return std::vector<std::vector<Real>>{{equation.derivative(x[0])}}; }};
}

void check_cubic(Context& context, const Json& proof, const Json& data, bool c1, const Real& p) {
    const CubicEquation equation{c1, p};
    if (context.string_at(proof, "kind", "proof") != "all") context.malformed("proof.kind", "expected \"all\"");
    const Json& cases = context.member(proof, "cases", "proof");
    if (!cases.is_array()) context.malformed("proof.cases", "expected an array");
    // A missing case is a gap in the proof (invalid), not a damaged file.
    context.require(cases.size() == 2, "proof.cases", "expected two cases: a Newton leaf and a partition");
    const std::string newton_path = "proof.cases[0]";
    const Json& newton = cases[0];
    if (context.string_at(newton, "kind", newton_path) != "newton") context.malformed(newton_path + ".kind", "expected newton");
    const Real box = context.box(context.member(newton, "box", newton_path), newton_path + ".box").at(0);
    const Real center = context.box(context.member(newton, "midpoint", newton_path), newton_path + ".midpoint").at(0);
    const Real derivative = context.box(context.member(newton, "derivative", newton_path), newton_path + ".derivative").at(0);
    const Real image = context.box(context.member(newton, "image", newton_path), newton_path + ".image").at(0);
    const Real stored_root = context.box(context.member(newton, "root", newton_path), newton_path + ".root").at(0);
    const Real s = replay_newton(
        context, [&](const Real& x) { return equation.value(x); }, [&](const Real& x) { return equation.derivative(x); },
        box, center, &derivative, &image, newton_path);
    context.require(subset(s, stored_root), newton_path + ".root",
                    "the stored root box " + text(stored_root) + " does not hold the root " + text(s));
    context.require(positive(s), newton_path + ".root", "the root may not be positive");

    const std::string below_path = "proof.cases[1]";
    const System system = one_dimensional(equation);
    const Box covered = check_partition(context, cases[1], below_path, [&](const Json& leaf, const Box& piece, const std::string& path) {
        check_root_leaf(context, system, leaf, piece, path, nullptr);
        context.require(context.string_at(leaf, "kind", path) != "krawczyk" || context.string_at(leaf, "status", path) == "none",
                        path, "a root below the Newton box: s would not be the smallest positive root");
    });
    context.current_step = below_path;
    context.require(covered.size() == 1 && mpfr_sgn(covered[0].lo()) <= 0 && mpfr_cmp(covered[0].hi(), box.lo()) >= 0,
                    below_path + ".box", "the root-free partition does not cover [0, lower end of the Newton box]");

    context.current_step = "claim.data";
    const Real t = equation.shift();
    check_quantities(context, data, c1 ? c1_basis(s, t) : c0_basis(s, t), p, {{"s", s}});
}

void check_o0(Context& context, const Json& proof, const Json& data, const Real& p) {
    if (context.string_at(proof, "kind", "proof") != "evaluation") context.malformed("proof.kind", "expected \"evaluation\"");
    context.current_step = "claim.data";
    const Real c = o0_height(p);
    check_quantities(context, data, o0_basis(c), p, {{"c", c}});
}

void check_o1(Context& context, const Json& proof, const Json& data, const Real& p) {
    const OctahedralEquations equations{p};
    const System system{[equations](const Box& x) {
                            const auto values = equations.value({x[0], x[1]});
                            return std::vector<Real>{values[0], values[1]};
                        },
                        [equations](const Box& x) {
                            const auto j = equations.jacobian({x[0], x[1]});
                            return std::vector<std::vector<Real>>{{j[0][0], j[0][1]}, {j[1][0], j[1][1]}};
                        }};
    if (context.string_at(proof, "kind", "proof") != "all") context.malformed("proof.kind", "expected \"all\"");
    const Json& cases = context.member(proof, "cases", "proof");
    if (!cases.is_array()) context.malformed("proof.cases", "expected an array");
    context.require(cases.size() == 1, "proof.cases", "expected one case: the partition");
    const std::string path = "proof.cases[0]";
    std::vector<Box> roots;
    const Box covered = check_partition(context, cases[0], path, [&](const Json& leaf, const Box& piece, const std::string& at) {
        if (piece.size() != 2) context.malformed(at + ".box", "expected a (q, s) box");
        check_root_leaf(context, system, leaf, piece, at, &roots);
    });
    context.current_step = path;
    const mpfr_prec_t precision = p.precision();
    context.require(covered.size() == 2 && subset(hull(integer(0, precision), integer(1, precision)), covered[0]) &&
                        subset(hull(integer(-1, precision), integer(1, precision)), covered[1]),
                    path + ".box", "the partition does not cover [0,1] x [-1,1]");
    for (std::size_t a = 0; a < roots.size(); ++a)
        for (std::size_t b = a + 1; b < roots.size(); ++b)
            context.require(disjoint(roots[a], roots[b]), path, "two pieces may hold the same root");
    const Real crossover = log(integer(3, precision)) / log(integer(4, precision));
    context.require(less(p, crossover), "inputs.p", "p is not below p*_o = ln3/ln4, where the Minkowski branch ends");
    context.require(!roots.empty(), path, "no root of Eq. (12) with q >= 0");
    std::size_t largest = 0;
    for (std::size_t k = 1; k < roots.size(); ++k)
        if (middle(roots[k][1]) > middle(roots[largest][1])) largest = k;
    for (std::size_t k = 0; k < roots.size(); ++k)
        context.require(k == largest || less(roots[k][1], roots[largest][1]), path,
                        "the root with the largest s is not determined");
    context.current_step = "claim.data";
    const Real& q = roots[largest][0];
    const Real& s = roots[largest][1];
    const Real l = equations.l();
    check_quantities(context, data, o1_basis(q, s, l), p, {{"l", l}, {"q", q}, {"s", s}});
}

void check_family_lattice(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const std::string family = context.string_at(data, "family", "claim.data");
    const mpq_class p = context.rational_at(data, "p", "claim.data");
    context.require(context.string_at(inputs, "family", "inputs") == family, "inputs.family",
                    "the input family differs from the claim's");
    context.require(context.rational_at(inputs, "p", "inputs") == p, "inputs.p", "the input p differs from the claim's");
    const mpq_class half(1, 2);
    const Real p_interval = rational(p, context.precision());
    const Json& proof = context.member(document, "proof", "");
    if (family == "C0" || family == "C1") {
        context.require(p >= 1, "inputs.p", "outside the domain p >= 1 of " + family);
        check_cubic(context, proof, data, family == "C1", p_interval);
    } else if (family == "O0") {
        context.require(p > half && p <= 1, "inputs.p", "outside the domain 1/2 < p <= 1 of O0");
        check_o0(context, proof, data, p_interval);
    } else if (family == "O1") {
        context.require(p >= half, "inputs.p", "outside the domain p >= 1/2 of O1");
        check_o1(context, proof, data, p_interval);
    } else {
        context.malformed("claim.data.family", "unknown family \"" + family + "\"");
    }
}

const ClaimKindRegistration registration("family-lattice", check_family_lattice);

}  // namespace

}  // namespace superpack_checker
