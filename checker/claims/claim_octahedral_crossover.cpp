// Claim kind "octahedral-crossover" (written by `superpack crossover octahedral --certificate`):
// Eq. (6), 2 (1 - 2^(1-2p))^(1/(2p)) = 1, has the root p*_o = ln3/ln4 on (1/2, 1] (for p > 1/2
// it is equivalent to 4^p = 3, NOTES.md 6.3); at p*_o the O0 lattice and the q -> 0 limit of the
// O1 lattice are one lattice with |det| = 4, so phi*_o = V_sb(p*_o) / 4.
//
// The checker encloses ln3/ln4 itself, replays interval Newton on Eq. (6) itself (the stored
// box) and requires its root to meet ln3/ln4, proves by its own bisection that Eq. (6) has one
// sign on the rest of (1/2, 1] (so that root is the only one), checks c(p*_o) and l(p*_o) contain 1/2 (the lemma's
// values), builds both bases at c = l = 1/2, q = 0, s = 1 with its own basis formulas (exact
// point intervals), proves B_O0 = U B_O1 exactly for the stated integer U with det U = +-1 and
// |det B_O0| = 4, and recomputes V_sb(p*_o) / 4.
//
// Keys read: claim.data {p, closed_form, phi, lattice {O0, O1, unimodular, abs_determinant}};
// inputs {from, to}; proof {kind, cases [newton {kind, box, midpoint, derivative, image, root},
// {kind: lattice-identity}]}.
#include "checker/claims/literature.hpp"
#include "checker/core/render.hpp"
#include "checker/core/replay.hpp"
#include "checker/formulas/equations_crossover.hpp"

namespace superpack_checker {

namespace {

using RationalMatrix = std::array<std::array<mpq_class, 3>, 3>;

RationalMatrix read_matrix(Context& context, const Json& node, const std::string& path) {
    if (!node.is_array() || node.size() != 3) context.malformed(path, "expected three rows");
    RationalMatrix m;
    for (int i = 0; i < 3; ++i) {
        const std::string row = path + "[" + std::to_string(i) + "]";
        if (!node[i].is_array() || node[i].size() != 3) context.malformed(row, "expected three entries");
        for (int j = 0; j < 3; ++j) {
            const Json holder{{"entry", node[i][j]}};
            m[i][j] = context.rational_at(holder, "entry", row + "[" + std::to_string(j) + "]");
        }
    }
    return m;
}

RationalMatrix product(const RationalMatrix& a, const RationalMatrix& b) {
    RationalMatrix c;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            c[i][k] = 0;
            for (int j = 0; j < 3; ++j) c[i][k] += a[i][j] * b[j][k];
        }
    return c;
}

mpq_class rational_determinant(const RationalMatrix& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The stated rational matrix is exactly the checker's basis (point intervals).
void check_same(Context& context, const RationalMatrix& stated, const Matrix3& own, const std::string& path) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const Real entry = rational(stated[i][j], own[i][j].precision());
            context.require(subset(entry, own[i][j]) && subset(own[i][j], entry),
                            path + "[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                            "differs from the checker's basis entry " + text(own[i][j]));
        }
}

// Eq. (6) has the one sign `sign` on [lo, hi]: direct evaluation, bisecting where it does not
// decide (near p = 1/2, c(p) = u^(1/(2p)) with u in [0, small] still gives 2c - 1 < 0).
bool prove_sign(const Real& q, int sign, int depth) {
    const Real value = 2 * o0_height(q) - integer(1, q.precision());
    if (sign < 0 ? negative(value) : positive(value)) return true;
    if (depth >= 30) return false;
    const Real center = midpoint(q);
    return prove_sign(hull(lower_point(q), center), sign, depth + 1) && prove_sign(hull(center, upper_point(q)), sign, depth + 1);
}

// Eq. (6) itself, f(p) = 2 c(p) - 1 with f'(p) = 2 c'(p), from the Newton case: exactly one root
// in the box, the box inside (1/2, 1], the root meeting ln3/ln4, and no other root on (1/2, 1]
// (f < 0 left of the box, > 0 right of it).
void replay_equation_six(Context& context, const Json& newton, const mpq_class& from, const Real& closed_form) {
    const mpfr_prec_t precision = context.precision();
    const std::string newton_path = "proof.cases[0]";
    if (context.string_at(newton, "kind", newton_path) != "newton") context.malformed(newton_path + ".kind", "expected newton");
    auto read = [&](const char* key) {
        return context.interval(context.member(newton, key, newton_path), newton_path + "." + key);
    };
    const Real box = read("box"), center = read("midpoint"), derivative = read("derivative"), image = read("image"),
               stored_root = read("root");
    const Real one = integer(1, precision);
    context.require(less(rational(from, precision), box) && mpfr_cmp(box.hi(), one.lo()) <= 0, newton_path + ".box",
                    "the Newton box is not inside (1/2, 1]");
    const Real root = replay_newton(
        context, [&](const Real& p) { return 2 * o0_height(p) - one; },
        [&](const Real& p) { return 2 * octahedral_height_with_slope(p).slope; }, box, center, &derivative, &image, newton_path);
    context.require(subset(root, stored_root), newton_path + ".root",
                    "the stored root " + text(stored_root) + " does not hold the checker's " + text(root));
    Real meet(precision);
    context.require(intersect(meet, root, closed_form), newton_path + ".root", "the root of Eq. (6) misses ln3/ln4");
    const Real half_point = rational(from, precision);
    context.require(prove_sign(hull(half_point, lower_point(box)), -1, 0), newton_path + ".box",
                    "Eq. (6) is not proved negative on [1/2, lower end of the box]");
    context.require(prove_sign(hull(upper_point(box), one), 1, 0), newton_path + ".box",
                    "Eq. (6) is not proved positive on [upper end of the box, 1]");
}

// The determinants the lattice identity proves: det U of B_O0 = U B_O1, and |det B_O0|.
struct LatticeIdentity {
    mpq_class unimodular_determinant, o0_determinant;
};

// At p*_o: c = l = 1/2 (3 = 4^p), q = 0, s = 1, so the stated O0 basis and the O1 basis at
// q = 0 are those of the checker, and the stated integer U with det U = +-1 maps one onto the
// other.
LatticeIdentity check_lattice_identity(Context& context, const Json& data, const Json& identity, const Real& closed_form) {
    const mpfr_prec_t precision = context.precision();
    const std::string lattice_path = "proof.cases[1]";
    if (context.string_at(identity, "kind", lattice_path) != "lattice-identity")
        context.malformed(lattice_path + ".kind", "expected lattice-identity");
    context.current_step = lattice_path;
    const Real half = rational(mpq_class(1, 2), precision);
    context.require(subset(half, o0_height(closed_form)), lattice_path, "c(ln3/ln4) does not contain 1/2");
    context.require(subset(half, OctahedralEquations{closed_form}.l()), lattice_path, "l(ln3/ln4) does not contain 1/2");
    const Json& lattice = context.member(data, "lattice", "claim.data");
    const RationalMatrix o0 = read_matrix(context, context.member(lattice, "O0", "claim.data.lattice"), "claim.data.lattice.O0");
    const RationalMatrix o1 = read_matrix(context, context.member(lattice, "O1", "claim.data.lattice"), "claim.data.lattice.O1");
    const RationalMatrix unimodular =
        read_matrix(context, context.member(lattice, "unimodular", "claim.data.lattice"), "claim.data.lattice.unimodular");
    check_same(context, o0, o0_basis(half), "claim.data.lattice.O0");
    const Real zero(precision);
    check_same(context, o1, o1_basis(zero, integer(1, precision), half), "claim.data.lattice.O1");
    for (const auto& row : unimodular)
        for (const mpq_class& entry : row)
            context.require(entry.get_den() == 1, "claim.data.lattice.unimodular", "not an integer matrix");
    const mpq_class det_u = rational_determinant(unimodular);
    context.require(det_u == 1 || det_u == -1, "claim.data.lattice.unimodular", "det U is not +-1");
    context.require(product(unimodular, o1) == o0, "claim.data.lattice.unimodular", "B_O0 != U B_O1");
    const mpq_class det = abs(rational_determinant(o0));
    context.require(context.rational_at(lattice, "abs_determinant", "claim.data.lattice") == det,
                    "claim.data.lattice.abs_determinant", "|det B_O0| is " + det.get_str());
    return {det_u, det};
}

std::string check_octahedral_crossover(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const mpq_class from = context.rational_at(inputs, "from", "inputs"), to = context.rational_at(inputs, "to", "inputs");
    context.require(from == mpq_class(1, 2) && to == 1, "inputs", "the claim is about Eq. (6) on (1/2, 1]");
    const mpfr_prec_t precision = context.precision();
    const Real closed_form = log(integer(3, precision)) / log(integer(4, precision));
    const Real stated_p = proved_enclosure(context, context.member(data, "p", "claim.data"), "claim.data.p", closed_form);
    const std::string closed_text = printed_value(Printed::p_star_o).closed_form;
    // The closed form is named by the claim, so it must be the one proved here (found by the fuzz test).
    context.require(context.string_at(data, "closed_form", "claim.data") == closed_text, "claim.data.closed_form",
                    "the checker proves p = " + closed_text + ", not another closed form");

    const Json& proof = context.member(document, "proof", "");
    if (context.string_at(proof, "kind", "proof") != "all") context.malformed("proof.kind", "expected \"all\"");
    const Json& cases = context.member(proof, "cases", "proof");
    if (!cases.is_array()) context.malformed("proof.cases", "expected an array");
    context.require(cases.size() == 2, "proof.cases", "expected two cases: Newton on Eq. (6) and the lattice identity");
    replay_equation_six(context, cases[0], from, closed_form);
    const LatticeIdentity identity = check_lattice_identity(context, data, cases[1], closed_form);
    const mpq_class& det_u = identity.unimodular_determinant;
    const mpq_class& det = identity.o0_determinant;
    context.current_step = "claim.data.phi";
    const Real stated_phi = proved_enclosure(context, context.member(data, "phi", "claim.data"), "claim.data.phi",
                                             superball_volume(closed_form) / rational(det, precision));
    return "Eq. (11) of " + std::string(paper_citation) + " (Sec. IV.A), 2 (1 - 2^(1-2p))^(1/(2p)) - 1 = 0, has exactly one root " +
           "p*_o on (1/2, 1], p*_o = " + closed_text + " in " + enclosure_words(stated_p) +
           " (claim.data.p); there the O0 lattice and the q -> 0 limit of the O1 (Minkowski) branch are one lattice, " +
           "B_O0 = U B_O1 with the integer U of claim.data.lattice (det U = " + exact_text(det_u) + "), |det B_O0| = " +
           exact_text(det) + ", and phi*_o = V_sb(p*_o) / " + exact_text(det) + " in " + enclosure_words(stated_phi) +
           " (claim.data.phi). The paper's " + printed_value_words(Printed::p_star_o, stated_p) + "; its " +
           printed_value_words(Printed::phi_star_o, stated_phi) + ".";
}

const ClaimKindRegistration registration("octahedral-crossover", check_octahedral_crossover);

}  // namespace

}  // namespace superpack_checker
