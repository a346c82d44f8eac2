// Claim kind "superdisk-optimum" (written by `superpack superdisk --p P --certificate FILE`):
// the densest lattice packing of the superdisk |x|^(2p) + |y|^(2p) <= 1 at an exact p > 1/2
// has density area / Delta(2K) in the stated enclosure, every minimiser t in [0, 1] of
// D(t) = det(u(t), v(t)) lies in the stated argmin intervals, and the named lattices
// (Lambda0 at t = 1, Lambda1 at t = 0) attain the optimum within its enclosure.
//
// The reduction Delta(2K) = 4 min D (Fejes Toth, Reinhardt-Mahler) and the symmetry reduction
// to t in [0, 1] are the premise stated in the file; the checker replays the computation:
// each piece's Krawczyk proof of v(t) with t the whole piece, its lower bound of D by the
// stated method (recomputed in MPFI, with D' by implicit differentiation derived by hand),
// the covering of [0, 1], the witness lattice, the area, and every claimed enclosure. The
// sentence states the premise (the checker's words, not the file's).
//
// Keys read: claim.data {p, area, optimal_determinant, optimal_phi, argmin_t, attained_by,
// lattices {Lambda0 | Lambda1 {t, determinant, phi}}}; inputs {p, p_decimal}; proof {kind,
// witness {t, search_box, determinant}, lattices {name {search_box}}, pieces [{t, verdict, method,
// search_box, lower_bound, center (naive_and_mean_value)}]}.
#include <algorithm>

#include "checker/core/render.hpp"
#include "checker/core/replay.hpp"
#include "checker/formulas/equations_superdisk.hpp"

namespace superpack_checker {

namespace {

struct Solution {
    Box v;    // (a, b): holds the unique solution for every t in the parameter interval
    Real d;   // D over the parameter interval and v
};

class SuperdiskChecker {
public:
    SuperdiskChecker(Context& context, const Real& p) : context_(context), equations_{p} {}

    // Replays Krawczyk for the contact system at the parameter interval t on `box` and, when
    // `tight`, re-proves it on the root box while that shrinks it further (slower; used only
    // when the first bound falls short). det(u, v) > 0 on the result identifies the root as
    // v(t) (the other solution, u - v, has det < 0).
    Solution solve(const Box& box, const Real& t, const std::string& path, bool tight = false) {
        context_.current_step = path;
        // At the point t = 0 the solution is known in closed form (v = (1/2, y1)); the search box
        // is not needed, and Krawczyk fails there for large q.
        if (mpfr_zero_p(t.lo()) && mpfr_zero_p(t.hi())) {
            const Real half = integer(1, t.precision()) / integer(2, t.precision());
            const Real height = equations_.axis_height();
            return {{half, height}, equations_.determinant(half, height, t)};
        }
        if (box.size() != 2) context_.malformed(path + ".search_box", "expected an (a, b) box");
        const SuperdiskEquations& equations = equations_;
        const System system{[&equations, t](const Box& x) {
                                const auto f = equations.contact(x[0], x[1], t);
                                return std::vector<Real>{f[0], f[1]};
                            },
                            [&equations, t](const Box& x) {
                                const auto j = equations.jacobian(x[0], x[1], t);
                                return std::vector<std::vector<Real>>{{j[0][0], j[0][1]}, {j[1][0], j[1][1]}};
                            }};
        KrawczykReplay replay = replay_krawczyk(system, box, 80);
        context_.require(replay.status == ReplayStatus::unique, path + ".search_box",
                         "the checker could not prove exactly one solution of the contact system in the box for every t "
                         "in " + text(t) + " (" + replay.reason + ")");
        Box root = replay.root;
        for (int round = 0; tight && round < 8; ++round) {
            const KrawczykReplay again = replay_krawczyk(system, root, 80);
            if (again.status != ReplayStatus::unique) break;
            const Width before = width(root[0]) + width(root[1]), after = width(again.root[0]) + width(again.root[1]);
            root = again.root;
            if (!(after < 0.9 * before)) break;
        }
        Solution solution{root, equations_.determinant(root[0], root[1], t)};
        context_.require(positive(solution.d), path + ".search_box",
                         "det(u, v) may be <= 0 on the solution: it may be u - v, not v");
        return solution;
    }

    Real derivative(const Solution& solution, const Real& t) const {
        return equations_.derivative(solution.v[0], solution.v[1], t);
    }

    Real a_priori_lower_bound(const Real& t, const std::string& path) const {
        context_.require(mpfr_sgn(t.lo()) >= 0 && mpfr_cmp_si(t.hi(), 1) <= 0, path + ".method",
                         "the a priori bound holds for t in [0, 1] only");
        return equations_.a_priori_lower_bound(t);
    }

private:
    Context& context_;
    SuperdiskEquations equations_;
};

bool within_some(const Real& t, const std::vector<Real>& components) {
    return std::any_of(components.begin(), components.end(), [&](const Real& c) { return subset(t, c); });
}

// The premise the checker does not replay: the reduction of the packing problem to the minimal
// inscribed hexagon (NOTES.md 7.1) and the symmetry reduction to t in [0, 1] (7.2).
const char* const premise =
    "Premise (not replayed): for a centrally symmetric convex disk K the densest packing of translates is a lattice "
    "packing (L. Fejes Toth 1950; C. A. Rogers 1951), of density area(K) / Delta(2K) = area(K) / (4 Delta(K)); and "
    "Delta(K) = min over u in bd K of D(u) = det(u, v(u)), where v(u) is the point of bd K with v - u in bd K and "
    "det(u, v) > 0, because every lattice with a basis u, v such that u, v, v - u lie on bd K is K-admissible and some "
    "critical lattice has such a basis (Reinhardt 1934, Mahler 1947; Cassels, An Introduction to the Geometry of "
    "Numbers, ch. V). The superdisk is convex for p >= 1/2 and strictly convex for p > 1/2, so v(u) is unique; with "
    "u(t) = (x, t x), x = (1 + t^q)^(-1/q), q = 2p, the symmetries of the square reduce every u to some t in [0, 1], "
    "and the lattice of u(t) has basis 2u, 2v and determinant 4 D(t).";

// The witness: an admissible hexagon lattice, so Delta(2K) <= 4 D(t_w). Returns D(t_w)'s upper
// end, the bound every discarded piece must exceed.
Real witness_upper_bound(const Json& proof, Context& context, SuperdiskChecker& checker) {
    const mpfr_prec_t precision = context.precision();
    const Real zero = integer(0, precision), one = integer(1, precision), four = integer(4, precision);
    const std::string witness_path = "proof.witness";
    const Json& witness = context.member(proof, "witness", "proof");
    const Real witness_t = context.interval(context.member(witness, "t", witness_path), witness_path + ".t");
    context.require(subset(witness_t, hull(zero, one)), witness_path + ".t", "t is not in [0, 1]");
    const Solution at_witness =
        checker.solve(context.box(context.member(witness, "search_box", witness_path), witness_path + ".search_box"),
                      witness_t, witness_path);
    check_encloses(context, context.member(witness, "determinant", witness_path), witness_path + ".determinant",
                   four * at_witness.d);
    return upper_point(at_witness.d);
}

// The checker's own lower bound of D on a piece t, by the piece's stated method; `tight`
// re-proves the solution boxes tighter, for when the first bound falls short of the stated one.
Real piece_lower_bound(const Json& piece, const Real& t, const std::string& method, const std::string& path, bool tight,
                       Context& context, SuperdiskChecker& checker) {
    if (method == "a_priori") return checker.a_priori_lower_bound(t, path);  // no solution needed
    const Box box = context.box(context.member(piece, "search_box", path), path + ".search_box");
    const Solution over = checker.solve(box, t, path, tight);
    context.current_step = path;
    Real bound = lower_point(over.d);  // the naive enclosure of D on the piece
    if (method == "naive_and_mean_value") {
        const Real center = context.interval(context.member(piece, "center", path), path + ".center");
        context.require(subset(center, t), path + ".center", "the center is not in the piece");
        const Solution at_center = checker.solve(box, center, path, tight);
        const Real slope = checker.derivative(over, t);
        const Real form = at_center.d + slope * (t - center);  // mean-value form of D on the piece
        if (mpfr_cmp(form.lo(), bound.lo()) > 0) bound = lower_point(form);
    } else if (method == "left_end" || method == "right_end") {
        const bool left = method == "left_end";
        const Real slope = checker.derivative(over, t);
        context.require(left ? positive(slope) : negative(slope), path + ".method",
                        std::string("D' is not certainly ") + (left ? "positive" : "negative") +
                            " on the piece: checker's D' = " + text(slope));
        const Solution at_end = checker.solve(box, left ? lower_point(t) : upper_point(t), path, tight);
        bound = lower_point(at_end.d);
    } else if (method != "naive") {
        context.malformed(path + ".method", "unknown lower-bound method \"" + method + "\"");
    }
    return bound;
}

// What the pieces leave open: the t of every piece kept (it may hold a minimiser) and the least
// lower bound of D over them (starting from the witness's D).
struct OpenPieces {
    std::vector<Real> t;
    Real lowest;
};

// One piece t: the stated lower bound of D must not exceed the checker's, and the verdict must
// follow from it: discarded (above the witness's D) or kept (monotone or bounded).
void replay_piece(const Json& piece, const Real& t, const std::string& path, const Real& upper, OpenPieces& open,
                  Context& context, SuperdiskChecker& checker) {
    const Real stated = context.interval(context.member(piece, "lower_bound", path), path + ".lower_bound");
    const std::string verdict = context.string_at(piece, "verdict", path);
    const std::string method = context.string_at(piece, "method", path);
    Real bound = piece_lower_bound(piece, t, method, path, false, context, checker);
    if (mpfr_cmp(stated.lo(), bound.lo()) > 0) bound = piece_lower_bound(piece, t, method, path, true, context, checker);
    context.require(mpfr_cmp(stated.lo(), bound.lo()) <= 0, path + ".lower_bound",
                    "the stated lower bound " + text(stated) + " of D exceeds the checker's " + text(bound));
    const bool monotone_method = method == "left_end" || method == "right_end";
    if (verdict == "discarded") {
        context.require(less(upper, bound), path + ".verdict",
                        "not discarded: the lower bound " + text(bound) + " does not exceed D of the witness " +
                            text(upper));
    } else if (verdict == "monotone" || verdict == "bounded") {
        context.require(monotone_method == (verdict == "monotone"), path + ".method",
                        "the method does not fit the verdict " + verdict);
        open.t.push_back(t);
        if (mpfr_cmp(bound.lo(), open.lowest.lo()) < 0) open.lowest = bound;
    } else {
        context.malformed(path + ".verdict", "unknown verdict \"" + verdict + "\"");
    }
}

// The pieces: they cover [0, 1]; each is discarded (its lower bound of D exceeds D of the
// witness) or may hold a minimiser (its lower bound enters min D).
OpenPieces replay_pieces(const Json& proof, const Real& upper, Context& context, SuperdiskChecker& checker) {
    const Json& pieces = context.member(proof, "pieces", "proof");
    if (!pieces.is_array()) context.malformed("proof.pieces", "expected an array");
    context.require(!pieces.empty(), "proof.pieces", "no pieces");
    OpenPieces open{{}, upper};
    Real reach(context.precision());
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const std::string path = "proof.pieces[" + std::to_string(k) + "]";
        const Json& piece = pieces[k];
        const Real t = context.interval(context.member(piece, "t", path), path + ".t");
        if (k == 0)
            context.require(mpfr_sgn(t.lo()) <= 0, path + ".t", "the pieces do not reach t = 0");
        else
            context.require(mpfr_cmp(t.lo(), reach.lo()) <= 0, path + ".t",
                            "a gap before this piece: [0, 1] is not covered");
        if (k == 0 || mpfr_cmp(t.hi(), reach.lo()) > 0) reach = upper_point(t);
        replay_piece(piece, t, path, upper, open, context, checker);
    }
    context.current_step = "proof.pieces";
    context.require(mpfr_cmp_si(reach.lo(), 1) >= 0, "proof.pieces", "the pieces do not reach t = 1");
    context.require(!open.t.empty(), "proof.pieces", "every piece discarded, even the witness's");
    return open;
}

// Every minimiser lies in a piece kept, so each kept piece must lie in an argmin component.
// Returns the components.
std::vector<Real> check_argmin(const Json& data, const std::vector<Real>& open_pieces, Context& context) {
    const Json& argmin_json = context.member(data, "argmin_t", "claim.data");
    if (!argmin_json.is_array()) context.malformed("claim.data.argmin_t", "expected an array");
    std::vector<Real> argmin;
    for (std::size_t k = 0; k < argmin_json.size(); ++k)
        argmin.push_back(context.interval(argmin_json[k], "claim.data.argmin_t[" + std::to_string(k) + "]"));
    for (const Real& t : open_pieces)
        context.require(within_some(t, argmin), "claim.data.argmin_t",
                        "the piece " + text(t) + " may hold a minimiser but lies in no argmin interval");
    return argmin;
}

// The named lattices: Lambda1 has u on an axis (t = 0), Lambda0 on the diagonal (t = 1). Each
// one's determinant 4 D(t) and density are replayed; returns the determinants by name.
std::vector<std::pair<std::string, Real>> check_named_lattices(const Json& data, const Json& proof, const Real& area,
                                                               Context& context, SuperdiskChecker& checker) {
    const mpfr_prec_t precision = context.precision();
    const Real zero = integer(0, precision), one = integer(1, precision), four = integer(4, precision);
    const Json& lattices = context.member(data, "lattices", "claim.data");
    const Json& lattice_proofs = context.member(proof, "lattices", "proof");
    if (!lattices.is_object()) context.malformed("claim.data.lattices", "expected an object");
    std::vector<std::pair<std::string, Real>> determinants;
    for (auto entry = lattices.begin(); entry != lattices.end(); ++entry) {
        const std::string name = entry.key();
        const std::string path = "claim.data.lattices." + name, proof_path = "proof.lattices." + name;
        if (name != "Lambda0" && name != "Lambda1") context.malformed(path, "unknown lattice \"" + name + "\"");
        const Json& lattice = context.member(lattices, name, "claim.data.lattices");
        const Real t = context.interval(context.member(lattice, "t", path), path + ".t");
        const Real& expected = name == "Lambda0" ? one : zero;
        context.require(subset(t, expected) && subset(expected, t), path + ".t",
                        name + " is the lattice at t = " + (name == "Lambda0" ? "1" : "0"));
        const Json& lattice_proof = context.member(lattice_proofs, name, "proof.lattices");
        const Solution solution =
            checker.solve(context.box(context.member(lattice_proof, "search_box", proof_path), proof_path + ".search_box"),
                          t, proof_path);
        context.current_step = path;
        const Real determinant = four * solution.d;
        check_encloses(context, context.member(lattice, "determinant", path), path + ".determinant", determinant);
        check_encloses(context, context.member(lattice, "phi", path), path + ".phi", area / determinant);
        determinants.emplace_back(name, determinant);
    }
    return determinants;
}

// The lattices claimed to attain the optimum: each is checked by name above, its determinant lies
// in the enclosure of Delta(2K) and its t in an argmin component. Returns them in words.
std::string check_attained(const Json& data, const std::vector<std::pair<std::string, Real>>& determinants,
                           const Real& claimed_determinant, const std::vector<Real>& argmin, Context& context) {
    const mpfr_prec_t precision = context.precision();
    const Real zero = integer(0, precision), one = integer(1, precision);
    const Json& attained = context.member(data, "attained_by", "claim.data");
    if (!attained.is_array()) context.malformed("claim.data.attained_by", "expected an array of lattice names");
    std::string attained_words;
    for (const Json& name_json : attained) {
        if (!name_json.is_string()) context.malformed("claim.data.attained_by", "expected lattice names");
        const std::string name = name_json.get<std::string>();
        const auto found = std::find_if(determinants.begin(), determinants.end(),
                                        [&](const auto& entry) { return entry.first == name; });
        context.require(found != determinants.end(), "claim.data.attained_by", name + " is not among claim.data.lattices");
        context.require(subset(found->second, claimed_determinant), "claim.data.attained_by",
                        "the determinant " + text(found->second) + " of " + name +
                            " is not within the enclosure of Delta(2K)");
        const Real t = name == "Lambda0" ? one : zero;
        context.require(within_some(t, argmin), "claim.data.attained_by",
                        "the t of " + name + " lies in no argmin interval");
        attained_words += std::string(attained_words.empty() ? "" : " and ") + name + " (t = " + (name == "Lambda0" ? "1" : "0") + ")";
    }
    return attained_words;
}

std::string check_superdisk_optimum(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const mpq_class p = context.rational_at(data, "p", "claim.data");
    context.require(context.rational_at(inputs, "p", "inputs") == p, "inputs.p", "the input p differs from the claim's");
    // p = 1/2 (the square tiles) and p < 1/2 (not convex) are excluded from this claim kind.
    context.require(p > mpq_class(1, 2), "inputs.p", "outside the domain p > 1/2 of superdisk-optimum certificates");
    const Json& proof = context.member(document, "proof", "");
    if (context.string_at(proof, "kind", "proof") != "superdisk-branch-and-bound")
        context.malformed("proof.kind", "expected \"superdisk-branch-and-bound\"");

    const mpfr_prec_t precision = context.precision();
    SuperdiskChecker checker(context, rational(p, precision));
    const Real upper = witness_upper_bound(proof, context, checker);
    const OpenPieces open = replay_pieces(proof, upper, context, checker);

    // The optimum: min D lies in [least lower bound of the pieces kept, D of the witness].
    context.current_step = "claim.data";
    const Real minimum = hull(open.lowest, upper);
    const Real optimal_determinant = integer(4, precision) * minimum;
    const Real area = superdisk_area(rational(p, precision));
    check_encloses(context, context.member(data, "area", "claim.data"), "claim.data.area", area);
    const Real claimed_determinant = proved_enclosure(context, context.member(data, "optimal_determinant", "claim.data"),
                                                      "claim.data.optimal_determinant", optimal_determinant);
    const Real claimed_phi = proved_enclosure(context, context.member(data, "optimal_phi", "claim.data"), "claim.data.optimal_phi",
                                              area / optimal_determinant);
    const std::vector<Real> argmin = check_argmin(data, open.t, context);
    const auto determinants = check_named_lattices(data, proof, area, context, checker);
    const std::string attained_words = check_attained(data, determinants, claimed_determinant, argmin, context);

    check_p_decimal(context, inputs, p);  // after the proof, which names a wrong p first

    // The sentence: the stated enclosures, each proved above to contain the checker's values.
    return std::string(premise) + " Under it: the densest lattice packing of the superdisk K: |x|^(2p) + |y|^(2p) <= 1 at p = " +
           exact_text(p) + " has packing density phi = area(K) / Delta(2K) in " + enclosure_words(claimed_phi) +
           " (claim.data.optimal_phi), with Delta(2K) = 4 min D(t) over t in [0, 1] in " + enclosure_words(claimed_determinant) +
           " (claim.data.optimal_determinant); every minimiser t in [0, 1] of D lies in an interval of claim.data.argmin_t; " +
           (attained_words.empty() ? std::string("no lattice checked by name (Lambda0 at t = 1, Lambda1 at t = 0) is shown to attain it")
                                   : "the optimum is attained within its enclosure by " + attained_words +
                                         " (4 D(t) lies in the enclosure of Delta(2K))") +
           ".";
}

const ClaimKindRegistration registration("superdisk-optimum", check_superdisk_optimum);

}  // namespace

}  // namespace superpack_checker
