// Claim kind "cubic-crossover" (written by `superpack crossover cubic --certificate`):
// g = phi_C1 - phi_C0 has exactly one zero p*_c in (1, 10], with C0 the denser family on
// (1, p*_c) and C1 on (p*_c, 10], and phi*_c = phi_C0(p*_c) = phi_C1(p*_c).
//
// The checker's own route (NOTES.md 8.5): with the closed-form determinants (proved equal to
// those of the bases by an exact polynomial identity), g has the sign and the zeros of
// h = 2 s0 + t - 3 t s1 - t^2, so V_sb drops out of the sign proof. For each stored piece of
// [1, 10] it proves s0(p), s1(p) over the whole piece (interval Newton with p as an interval
// parameter, from the stored boxes), then the stated sign of h by the first rule that works:
// h(P) one-signed; h' one-signed on P and the sign known at the left end (h(1) = 0 exactly, or
// the sign the previous piece proved at its right end); the mean value form; else it bisects the
// piece itself. The one root piece is proved by interval Newton on h in p. h(1) = 0 is an exact
// computation in Q(sqrt2) (both cubic lattices are FCC at p = 1).
//
// Keys read: claim.data {difference, from, to, p, phi, sign_left, sign_right, densest_left,
// densest_right}; inputs {from, to}; proof {kind, at_start {kind, p, s_C0 {a, b}, s_C1 {a, b}},
// pieces [{p, claim, s_C0 {box}, s_C1 {box}, root (the root piece)}]}.
#include <cstdlib>
#include <iostream>

#include "checker/claims/literature.hpp"
#include "checker/core/render.hpp"
#include "checker/core/replay.hpp"
#include "checker/formulas/equations_crossover.hpp"
#include "checker/formulas/smallest_root.hpp"

namespace superpack_checker {

namespace {

// The checker bisects a piece at most this deep before it gives up on it.
constexpr int max_depth = 12;

// Both contact roots known over a p interval: the piece proof.
struct PieceRoots {
    Real s0, s1;
};

ValueAndSlope crossover_at(const PieceRoots& known, const Real& p) {
    const CubicEquation c0{false, p}, c1{true, p};
    const Real s0 = refine_known_root(c0, known.s0), s1 = refine_known_root(c1, known.s1);
    return cubic_crossover_function(cubic_root_with_slope(c0, s0), cubic_root_with_slope(c1, s1), halving_shift(p));
}

int sign_of(const Real& x) { return positive(x) ? 1 : negative(x) ? -1 : 0; }

// Proves sign(h) = `sign` on (lo, hi] of q given the sign `left` of h at the lower end (0:
// h vanishes there), bisecting up to max_depth. Counts the extra pieces it made.
bool prove_sign(const PieceRoots& known, const Real& q, int sign, int left, int depth, long& bisections) {
    const ValueAndSlope h = crossover_at(known, q);
    if (sign_of(h.value) == sign) return true;
    if (sign_of(h.slope) == sign && left * sign >= 0) return true;
    const Real center = midpoint(q);
    const Real centered = crossover_at(known, center).value + h.slope * (q - center);
    if (sign_of(centered) == sign) return true;
    if (depth >= max_depth) return false;
    ++bisections;
    const Real left_half = hull(lower_point(q), center), right_half = hull(center, upper_point(q));
    return prove_sign(known, left_half, sign, left, depth + 1, bisections) &&
           prove_sign(known, right_half, sign, sign, depth + 1, bisections);
}

Surd read_surd(Context& context, const Json& node, const std::string& key, const std::string& path) {
    const Json& value = context.member(node, key, path);
    return {context.rational_at(value, "a", path + "." + key), context.rational_at(value, "b", path + "." + key)};
}

// h(1) = 0: the stated s0, s1 solve Eq. 2 and Eq. 9 at p = 1 exactly, are positive and below 1
// (where f is increasing, so they are the smallest positive roots), and give h = 0.
void check_sphere_point(Context& context, const Json& node, const std::string& path) {
    context.current_step = path;
    if (context.string_at(node, "kind", path) != "sphere-point") context.malformed(path + ".kind", "expected sphere-point");
    context.require(context.rational_at(node, "p", path) == 1, path + ".p", "the lemma is at p = 1");
    const Surd s0 = read_surd(context, node, "s_C0", path), s1 = read_surd(context, node, "s_C1", path);
    const Surd one{1, 0};
    for (const auto& [s, c1] : {std::pair<Surd, bool>{s0, false}, {s1, true}}) {
        const std::string at = path + (c1 ? ".s_C1" : ".s_C0");
        context.require(sphere_point_cubic_equation(c1, s) == Surd{0, 0}, at, "not a root of the contact equation at p = 1");
        context.require(sign(s) > 0 && sign(one - s) > 0, at, "not in (0, 1)");
        const mpfr_prec_t precision = context.precision();
        context.require(positive(cubic_slope_in_s(CubicEquation{c1, integer(1, precision)},
                                                  hull(integer(0, precision), integer(1, precision)))),
                        at, "f not proved increasing on [0, 1]");
    }
    context.require(sphere_point_crossover_function(s0, s1) == Surd{0, 0}, path, "h(1) is not 0");
}

int parse_sign(Context& context, const std::string& text, const std::string& path) {
    if (text == "negative") return -1;
    if (text == "positive") return 1;
    context.malformed(path, "expected negative or positive");
    return 0;
}

// The root piece p: h' has one sign `rise` on it and interval Newton maps it inside itself, so
// it holds exactly one zero of h; Newton is iterated while it tightens. Returns the root's
// enclosure and sets rise.
Real replay_root_piece(Context& context, const PieceRoots& known, const Real& p, const std::string& path, int& rise) {
    const mpfr_prec_t precision = context.precision();
    const ValueAndSlope h = crossover_at(known, p);
    rise = sign_of(h.slope);
    context.require(rise != 0, path, "h' may vanish on the piece: " + text(h.slope));
    const Real center = midpoint(p);
    const Real image = center - crossover_at(known, center).value / h.slope;
    context.require(interior_subset(image, p), path, "N(P) = " + text(image) + " is not inside P = " + text(p));
    Real current(precision);
    intersect(current, image, p);
    for (int iteration = 0; iteration < 200; ++iteration) {
        const Real mid = midpoint(current);
        const Real next_image = mid - crossover_at(known, mid).value / crossover_at(known, current).slope;
        Real next(precision);
        context.require(intersect(next, next_image, current), path, "a Newton iterate lost the root (inconsistent)");
        const Width before = width(current), after = width(next);
        current = next;
        if (after == 0.0 || after >= 0.75 * before) break;
    }
    return current;
}

// What the sign partition of (1, to] proves: each piece's sign of h (0 for the root piece), the
// root piece's index, the root's enclosure, the sign of h' there, both contact roots on that
// piece, and how many extra pieces the checker cut.
struct SignPartition {
    std::vector<int> claims;
    std::size_t root_index;
    Real root;
    int rise = 0;
    PieceRoots root_roots;
    long bisections = 0;
};

// The pieces: they tile (from, to] in order; each has its contact roots replayed, then either
// holds the one root of h or has h of one stated sign, proved from the sign at its lower end.
SignPartition replay_sign_partition(Context& context, const Json& pieces, const mpq_class& from, const mpq_class& to) {
    const mpfr_prec_t precision = context.precision();
    Real end = rational(from, precision);  // exact: 1
    int left = 0;                          // the sign of h at `end`: h(1) = 0
    const Real unknown(precision);
    SignPartition partition{{}, pieces.size(), unknown, 0, PieceRoots{unknown, unknown}, 0};
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const std::string path = "proof.pieces[" + std::to_string(k) + "]";
        const Json& piece = pieces[k];
        const Real p = context.interval(context.member(piece, "p", path), path + ".p");
        context.require(mpfr_equal_p(p.lo(), end.hi()) != 0, path + ".p",
                        "does not start where the previous piece ends (" + text(end) + ")");
        context.require(mpfr_cmp(p.lo(), p.hi()) < 0, path + ".p", "an empty piece");
        end = upper_point(p);
        const CubicEquation c0{false, p}, c1{true, p};
        const PieceRoots known{replay_smallest_root(context, c0, context.member(piece, "s_C0", path), path + ".s_C0"),
                               replay_smallest_root(context, c1, context.member(piece, "s_C1", path), path + ".s_C1")};
        context.current_step = path;
        const std::string stated = context.string_at(piece, "claim", path);
        if (stated == "root") {
            context.require(partition.root_index == pieces.size(), path + ".claim", "a second root piece");
            partition.root_index = k;
            partition.root = replay_root_piece(context, known, p, path, partition.rise);
            partition.root_roots = known;
            check_encloses(context, context.member(piece, "root", path), path + ".root", partition.root);
            partition.claims.push_back(0);
            left = partition.rise;
            continue;
        }
        const int sign = parse_sign(context, stated, path + ".claim");
        context.require(prove_sign(known, p, sign, left, 0, partition.bisections), path,
                        "the checker could not prove h " + stated + " on the piece");
        partition.claims.push_back(sign);
        left = sign;
    }
    context.require(mpfr_equal_p(end.hi(), rational(to, precision).hi()) != 0, "proof.pieces",
                    "the pieces end at " + text(end) + ", not at the end of the interval");
    context.require(partition.root_index < pieces.size(), "proof.pieces", "no root piece");
    return partition;
}

// phi*_c from both families at the root: each encloses it, so their meet does.
Real crossover_density(Context& context, const SignPartition& partition) {
    const mpfr_prec_t precision = context.precision();
    const Real& root = partition.root;
    const CubicEquation c0{false, root}, c1{true, root};
    const ValueAndSlope t = halving_shift(root), volume = superball_volume_with_slope(root);
    const Real unused_slope(precision);  // only the values are needed here
    const ValueAndSlope s0{refine_known_root(c0, partition.root_roots.s0), unused_slope};
    const ValueAndSlope s1{refine_known_root(c1, partition.root_roots.s1), unused_slope};
    const Real phi0 = volume.value / cubic_abs_determinant(false, s0, t).value;
    const Real phi1 = volume.value / cubic_abs_determinant(true, s1, t).value;
    Real phi(precision);
    context.require(intersect(phi, phi0, phi1), "claim.data.phi", "phi_C0 and phi_C1 at p*_c are disjoint");
    return phi;
}

std::string check_cubic_crossover(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const mpq_class from = context.rational_at(inputs, "from", "inputs"), to = context.rational_at(inputs, "to", "inputs");
    context.require(context.rational_at(data, "from", "claim.data") == from, "claim.data.from", "differs from the input");
    context.require(context.rational_at(data, "to", "claim.data") == to, "claim.data.to", "differs from the input");
    context.require(from == 1 && to > 1, "inputs.from", "the claim starts at the sphere point p = 1");
    if (context.string_at(data, "difference", "claim.data") != "phi_C1(p) - phi_C0(p)")
        context.malformed("claim.data.difference", "expected \"phi_C1(p) - phi_C0(p)\"");
    const mpfr_prec_t precision = context.precision();
    const std::string identity = determinant_identity_failure(precision);
    context.require(identity.empty(), "claim.data", "closed-form determinant disagrees with the basis: " + identity);

    const Json& proof = context.member(document, "proof", "");
    if (context.string_at(proof, "kind", "proof") != "sign-partition") context.malformed("proof.kind", "expected sign-partition");
    check_sphere_point(context, context.member(proof, "at_start", "proof"), "proof.at_start");
    const Json& pieces = context.member(proof, "pieces", "proof");
    if (!pieces.is_array()) context.malformed("proof.pieces", "expected an array");
    context.require(!pieces.empty(), "proof.pieces", "no pieces");
    const SignPartition partition = replay_sign_partition(context, pieces, from, to);
    const std::vector<int>& claims = partition.claims;
    const std::size_t root_index = partition.root_index;

    context.current_step = "claim.data";
    const int sign_left = parse_sign(context, context.string_at(data, "sign_left", "claim.data"), "claim.data.sign_left");
    const int sign_right = parse_sign(context, context.string_at(data, "sign_right", "claim.data"), "claim.data.sign_right");
    context.require(sign_right == partition.rise && sign_left == -partition.rise, "claim.data.sign_right",
                    "h changes sign the other way at the root");
    for (std::size_t k = 0; k < claims.size(); ++k)
        if (k != root_index)
            context.require(claims[k] == (k < root_index ? sign_left : sign_right),
                            "proof.pieces[" + std::to_string(k) + "].claim", "a piece on the wrong side of the root for its sign");
    const std::string densest_left = context.string_at(data, "densest_left", "claim.data");
    const std::string densest_right = context.string_at(data, "densest_right", "claim.data");
    context.require(densest_left == (sign_left < 0 ? "C0" : "C1"), "claim.data.densest_left", "g < 0 means C0 is denser");
    context.require(densest_right == (sign_right < 0 ? "C0" : "C1"), "claim.data.densest_right", "g > 0 means C1 is denser");

    const Real stated_p = proved_enclosure(context, context.member(data, "p", "claim.data"), "claim.data.p", partition.root);
    const Real phi = crossover_density(context, partition);
    const Real stated_phi = proved_enclosure(context, context.member(data, "phi", "claim.data"), "claim.data.phi", phi);
    // For measurements (NOTES.md 8.5): how often the checker had to cut a stored piece, and its own p*_c.
    if (std::getenv("SUPERPACK_CHECKER_TRACE"))
        std::cerr << "cubic-crossover: checker bisections " << partition.bisections << ", p*_c in " << text(partition.root)
                  << " width " << width(partition.root) << "\n";
    auto larger = [](int sign) { return sign < 0 ? "phi_C0 > phi_C1" : "phi_C1 > phi_C0"; };
    return "g(p) = phi_C1(p) - phi_C0(p), with phi = V_sb(p) / |det B| of the C1 and C0 lattices of " + std::string(paper_citation) +
           " (Secs. III.B and III.A), has exactly one zero p*_c in (1, " + exact_text(to) + "], p*_c in " +
           enclosure_words(stated_p) + " (claim.data.p); g is " + (sign_left < 0 ? "< 0" : "> 0") + " on (1, p*_c) (" +
           larger(sign_left) + ") and " + (sign_right < 0 ? "< 0" : "> 0") + " on (p*_c, " + exact_text(to) + "] (" +
           larger(sign_right) + "); phi*_c = phi_C0(p*_c) = phi_C1(p*_c) in " + enclosure_words(stated_phi) +
           " (claim.data.phi). The paper's " + printed_value_words(Printed::p_star_c, stated_p) + "; its " +
           printed_value_words(Printed::phi_star_c, stated_phi) + ".";
}

const ClaimKindRegistration registration("cubic-crossover", check_cubic_crossover);

}  // namespace

}  // namespace superpack_checker
