// Claim kind "lattice-check" (written by `superpack check-lattice --basis ... --certificate`):
// the lattice with an exact basis is a packing of the superball at an exact p >= 1/2 with N
// contacts, or is not a packing (a witness of 2p-norm < 2). NOTES.md sections 5 and 8.
//
// The checker trusts no list in the file. It checks the basis reduction R = U B exactly (U
// integral, det U = +-1), recomputes the coefficient bound of R exactly in rationals (Cramer
// and Hoelder: |a_i| <= floor(2 ||r_j x r_k||_1 / |det R|)), enumerates every
// triple of that box itself, and for each one whose exact coordinates are all at most 2 in size
// (a larger coordinate already gives norm > 2) requires it to be listed, recomputes its norm
// enclosure in MPFI, and decides it: certainly > 2, certainly < 2, or norm exactly 2 by an
// exact rational test. Anything else is a rejection. Listed candidates outside its box (the
// producer's bound may be larger) are decided the same way.
//
// Keys read: claim.data {basis, p, packing, contacts, contact_vectors | witness}; inputs {basis,
// p, p_decimal}; proof {kind, coefficient_bound, bound_data {determinant, cross_norms},
// candidates [{coefficients, norm, status}], contacts [{coefficients, vector}] (a packing only)}.
#include <set>
#include <stdexcept>

#include "checker/core/limits.hpp"
#include "checker/core/render.hpp"
#include "checker/formulas/equations.hpp"
#include "checker/formulas/lattice_enumeration.hpp"

namespace superpack_checker {

namespace {

using Vector = RationalVector;

Real norm_enclosure(const Vector& v, const Real& two_p, mpfr_prec_t precision) {
    return lattice_norm({rational(v[0], precision), rational(v[1], precision), rational(v[2], precision)}, two_p);
}

// What the checker's decisions of the candidates found: the contacts (norm exactly 2) and how
// many candidates have norm certainly below 2.
struct Decisions {
    std::set<Triple> contacts;
    long below = 0;
};

// Decides one listed candidate t (its index in proof.candidates): its norm enclosure must contain
// the checker's, and its status must be the checker's (or undecided beside a witness).
void decide_candidate(Context& context, const Json& proof, const RationalMatrix& rows, const mpq_class& two_p_exact,
                      const Real& two_p, bool packing, const Triple& t, std::size_t index, Decisions& decisions) {
    const mpfr_prec_t precision = context.precision();
    const Real two = integer(2, precision);
    const Vector v = combination(rows, t);
    const std::string path = "proof.candidates[" + std::to_string(index) + "]";
    context.current_step = path;
    const Json& entry = proof.at("candidates")[index];  // an array, checked by replay_candidates
    const Real norm = norm_enclosure(v, two_p, precision);
    check_encloses(context, context.member(entry, "norm", path), path + ".norm", norm);
    std::string status;
    if (less(norm, two)) {
        status = "below";
        ++decisions.below;
        context.require(!packing, path, "the vector " + triple_text(t) + " has norm " + text(norm) +
                                            " < 2: the lattice is not a packing");
    } else if (less(two, norm)) {
        status = "above";
    } else if (norm_is_exactly_two(v, two_p_exact)) {
        status = "contact";
        decisions.contacts.insert(t);
    } else {
        // Harmless beside a witness; fatal to a packing claim.
        context.require(!packing, path, "the norm enclosure " + text(norm) + " of " + triple_text(t) +
                                            " holds 2 and no exact test proves the norm equal to 2");
        status = "undecided";
    }
    // The producer's coarser arithmetic may leave undecided what the checker decides.
    const std::string stated_status = context.string_at(entry, "status", path);
    context.require(stated_status == status || (!packing && stated_status == "undecided"), path + ".status",
                    "the stated status \"" + stated_status + "\" differs from the checker's \"" + status + "\"");
}

// The claimed contact count and vectors must be the checker's contacts, stated in the given
// basis (the checker's contacts t in R are t U there), each +- pair once. Returns the count.
long check_claimed_contacts(Context& context, const Json& data, const std::set<Triple>& contacts,
                            const Reduction& reduction) {
    const long count = read_integer(context, context.member(data, "contacts", "claim.data"), "claim.data.contacts", 0,
                                    2 * static_cast<long>(max_contact_pairs), "max_contact_pairs");
    context.require(count == 2 * static_cast<long>(contacts.size()), "claim.data.contacts",
                    "the checker finds " + std::to_string(2 * contacts.size()) + " contacts");
    const Json& vectors = context.member(data, "contact_vectors", "claim.data");
    if (!vectors.is_array()) context.malformed("claim.data.contact_vectors", "expected an array");
    std::set<Triple> stated, given, distinct;  // distinct: no vector listed twice in place of another
    for (std::size_t k = 0; k < vectors.size(); ++k) {
        Triple t = read_triple(context, vectors[k], "claim.data.contact_vectors[" + std::to_string(k) + "]");
        distinct.insert(t);
        if (!canonical(t)) t = {-t[0], -t[1], -t[2]};
        stated.insert(t);
    }
    for (const Triple& t : contacts) {
        Triple u = reduction.given(t);
        if (!canonical(u)) u = {-u[0], -u[1], -u[2]};
        given.insert(u);
    }
    context.require(stated == given && distinct.size() == 2 * contacts.size() && vectors.size() == distinct.size(),
                    "claim.data.contact_vectors",
                    "the stated contact vectors differ from the checker's");
    return count;
}

// The proof's list of decided contacts, each with its exact vector, must be the checker's.
void check_proof_contacts(Context& context, const Json& proof, const RationalMatrix& rows, const std::set<Triple>& contacts) {
    const Json& decided = context.member(proof, "contacts", "proof");
    if (!decided.is_array()) context.malformed("proof.contacts", "expected an array");
    std::set<Triple> listed_contacts;
    for (std::size_t k = 0; k < decided.size(); ++k) {
        const std::string path = "proof.contacts[" + std::to_string(k) + "]";
        const Triple t = read_triple(context, context.member(decided[k], "coefficients", path), path + ".coefficients");
        const Vector v = combination(rows, t);
        const Json& vector = context.member(decided[k], "vector", path);
        if (!vector.is_array() || vector.size() != 3) context.malformed(path + ".vector", "expected three rationals");
        for (int j = 0; j < 3; ++j) {
            const Json holder{{std::to_string(j), vector[j]}};
            context.require(context.rational_at(holder, std::to_string(j), path + ".vector") == v[j], path + ".vector",
                            "not the lattice vector of " + triple_text(t));
        }
        listed_contacts.insert(t);
    }
    context.require(listed_contacts == contacts, "proof.contacts", "the decided contacts differ from the checker's");
}

// Not a packing: some candidate is below 2, and the claimed witness (in the given basis) has
// norm certainly below 2. Returns the sentence.
std::string check_witness(Context& context, const Json& data, const RationalMatrix& basis, const mpq_class& p,
                          const Real& two_p, long below) {
    const mpfr_prec_t precision = context.precision();
    context.require(below > 0, "claim.data.packing", "no candidate has norm < 2, yet the claim says not a packing");
    const Json& witness = context.member(data, "witness", "claim.data");
    const Triple t = read_triple(context, context.member(witness, "coefficients", "claim.data.witness"),
                                 "claim.data.witness.coefficients");
    context.require(t != Triple{0, 0, 0}, "claim.data.witness", "the zero vector is no witness");
    const Real norm = norm_enclosure(combination(basis, t), two_p, precision);
    const Real stated =
        proved_below(context, context.member(witness, "norm", "claim.data.witness"), "claim.data.witness.norm", norm, 2);
    return "The lattice with basis rows " + basis_words(basis) + " at p = " + exact_text(p) +
           " is not a packing of the superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1: the lattice vector " + triple_text(t) +
           " has 2p-norm in " + enclosure_words(stated) + " < 2.";
}

std::string check_lattice_check(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const Json& proof = context.member(document, "proof", "");
    const mpfr_prec_t precision = context.precision();

    const LatticeClaim read = read_lattice_claim(context, data, inputs);
    const RationalMatrix& basis = read.basis;
    const mpq_class& p = read.p;
    const bool packing = read.packing;
    context.require(p >= mpq_class(1, 2), "inputs.p", "the packing criterion needs p >= 1/2 (a convex superball)");
    if (context.string_at(proof, "kind", "proof") != "enumeration") context.malformed("proof.kind", "expected \"enumeration\"");

    // The enumeration runs on the reduced basis R = U B (rows r_i), the same lattice.
    const Reduction reduction = replay_reduction(context, proof, basis);
    const RationalMatrix& rows = reduction.reduced;

    const mpq_class two_p_exact = 2 * p;
    const Real two_p = rational(two_p_exact, precision);
    Decisions decisions;
    auto decide = [&](const Triple& t, std::size_t index) {
        decide_candidate(context, proof, rows, two_p_exact, two_p, packing, t, index, decisions);
    };
    const mpq_class det = replay_candidates(context, proof, rows, decide);
    check_p_decimal(context, inputs, p);  // after the proof, which names a wrong p first

    context.current_step = "claim.data";
    if (!packing) return check_witness(context, data, basis, p, two_p, decisions.below);
    const long count = check_claimed_contacts(context, data, decisions.contacts, reduction);
    check_proof_contacts(context, proof, rows, decisions.contacts);
    // The sentence: the contacts verified, and |det B| exactly.
    return "The lattice with basis rows " + basis_words(basis) + " at p = " + exact_text(p) +
           " is a packing of the superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1 with " + std::to_string(count) +
           " contacts (every nonzero lattice vector has 2p-norm >= 2, with equality exactly for the contact vectors), " +
           "of packing density V_sb(p) / |det B| with |det B| = " + exact_text(abs(det)) + ".";
}

const ClaimKindRegistration registration("lattice-check", check_lattice_check);

}  // namespace

}  // namespace superpack_checker
