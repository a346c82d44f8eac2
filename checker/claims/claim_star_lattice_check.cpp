// Claim kind "star-lattice-check" (written by `superpack check-lattice --basis ... --certificate`
// and `best --certificate` below p = 1/2): the lattice with an exact basis is a packing of the
// concave superball K = {|x|^(2p) + |y|^(2p) + |z|^(2p) <= 1} at an exact p < 1/2 (the interiors
// of K and K + v are disjoint for every nonzero lattice vector v), or is not (a rational point
// inside K and K + v). NOTES.md 13.5.
//
// A packing: the checker replays the basis reduction and the coefficient bound exactly and
// enumerates the box itself (lattice_enumeration.hpp); every triple whose vector has all
// coordinates at most 2 in size must be listed, and each listed one is decided by the checker's
// own closed-form case test (star_cases.hpp) or, with a coordinate of size 2 (K lies in
// [-1, 1]^3), exactly; anything but "disjoint" is a rejection. Not a packing: the witness point x
// is rational, and g(x) < 1 and g(x - v) < 1 are checked in MPFI (g = sum |x_i|^(2p)); nothing
// else is needed.
//
// Keys read: claim.data {basis, p, packing, witness {coefficients, point, values} (not a
// packing)}; inputs {basis, p, p_decimal}; proof {kind "enumeration", reduction, coefficient_bound,
// bound_data, candidates [{coefficients, status}]} for a packing, {kind "witness-point"} otherwise.
#include "checker/core/render.hpp"
#include "checker/formulas/equations.hpp"
#include "checker/formulas/lattice_enumeration.hpp"
#include "checker/formulas/star_cases.hpp"

namespace superpack_checker {

namespace {

// g(x) = sum |x_i|^q at a rational point, in MPFI.
Real gauge_power(const RationalVector& x, const Real& q, mpfr_prec_t precision) {
    return pow_abs(rational(x[0], precision), q) + pow_abs(rational(x[1], precision), q) + pow_abs(rational(x[2], precision), q);
}

std::string body_words(const mpq_class& p) {
    return "the concave superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1 at p = " + exact_text(p);
}

std::string check_packing(Context& context, const LatticeClaim& read, const Json& proof) {
    if (context.string_at(proof, "kind", "proof") != "enumeration") context.malformed("proof.kind", "expected \"enumeration\"");
    const Reduction reduction = replay_reduction(context, proof, read.basis);
    const RationalMatrix& rows = reduction.reduced;
    const mpq_class q = 2 * read.p;
    const mpq_class det = replay_candidates(context, proof, rows, [&](const Triple& t, std::size_t index) {
        const std::string path = "proof.candidates[" + std::to_string(index) + "]";
        context.current_step = path;
        const RationalVector v = combination(rows, t);
        const bool apart = abs(v[0]) >= 2 || abs(v[1]) >= 2 || abs(v[2]) >= 2;
        const StarVerdict verdict = apart ? StarVerdict::disjoint : star_cases(v, q, context.precision());
        context.require(verdict == StarVerdict::disjoint, path,
                        "the translate by " + triple_text(t) + (verdict == StarVerdict::overlapping
                                                                     ? " meets K in interior points: the lattice is not a packing"
                                                                     : " is not certainly disjoint from K by the case test"));
        const std::string status = context.string_at(proof.at("candidates")[index], "status", path);
        context.require(status == "disjoint", path + ".status", "the stated status \"" + status + "\" is not the checker's \"disjoint\"");
    });
    return "The lattice with basis rows " + basis_words(read.basis) + " is a packing of " + body_words(read.p) +
           " (for every nonzero lattice vector v the interiors of K and K + v are disjoint), of packing density "
           "V_sb(p) / |det B| with |det B| = " +
           exact_text(abs(det)) + ".";
}

std::string check_overlap(Context& context, const LatticeClaim& read, const Json& data, const Json& proof) {
    if (context.string_at(proof, "kind", "proof") != "witness-point") context.malformed("proof.kind", "expected \"witness-point\"");
    const std::string path = "claim.data.witness";
    context.current_step = path;
    const Json& witness = context.member(data, "witness", "claim.data");
    const Triple t = read_triple(context, context.member(witness, "coefficients", path), path + ".coefficients");
    context.require(t != Triple{0, 0, 0}, path, "the zero vector is no witness");
    const RationalVector v = combination(read.basis, t);
    const Json& point = context.member(witness, "point", path);
    if (!point.is_array() || point.size() != 3) context.malformed(path + ".point", "expected three rationals");
    RationalVector x, shifted;
    for (int j = 0; j < 3; ++j) {
        const Json holder{{std::to_string(j), point[j]}};
        x[j] = context.rational_at(holder, std::to_string(j), path + ".point");
        shifted[j] = x[j] - v[j];
    }
    const Json& values = context.member(witness, "values", path);
    if (!values.is_array() || values.size() != 2) context.malformed(path + ".values", "expected g(x) and g(x - v)");
    const mpfr_prec_t precision = context.precision();
    const Real q = rational(2 * read.p, precision);
    // g(x) < 1: x inside K; g(x - v) < 1: x inside K + v.
    const Real stated_inside = proved_below(context, values[0], path + ".values[0]", gauge_power(x, q, precision), 1);
    const Real stated_translate = proved_below(context, values[1], path + ".values[1]", gauge_power(shifted, q, precision), 1);
    return "The lattice with basis rows " + basis_words(read.basis) + " is not a packing of " + body_words(read.p) +
           ": the point x = (" + exact_text(x[0]) + ", " + exact_text(x[1]) + ", " + exact_text(x[2]) +
           ") lies inside K and K + v for the lattice vector v = " + triple_text(t) + ", with g(x) in " +
           enclosure_words(stated_inside) + " and g(x - v) in " + enclosure_words(stated_translate) + ", both < 1.";
}

std::string check_star_lattice_check(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const Json& proof = context.member(document, "proof", "");
    const LatticeClaim read = read_lattice_claim(context, data, inputs);
    context.require(read.p > 0 && read.p < mpq_class(1, 2), "inputs.p", "the star-body test is for 0 < p < 1/2 (a concave superball)");
    const std::string sentence = read.packing ? check_packing(context, read, proof) : check_overlap(context, read, data, proof);
    check_p_decimal(context, inputs, read.p);
    return sentence;
}

const ClaimKindRegistration registration("star-lattice-check", check_star_lattice_check);

}  // namespace

}  // namespace superpack_checker
