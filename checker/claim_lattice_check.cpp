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
#include <map>
#include <set>
#include <stdexcept>

#include "checker/equations.hpp"
#include "checker/equations_lattice.hpp"
#include "checker/render.hpp"
#include "checker/replay.hpp"
#include "checker/triple.hpp"

namespace superpack_checker {

namespace {

using Vector = RationalVector;
using Matrix = RationalMatrix;

// Triples in the coefficient box, prod (2 N_i + 1): the enumeration's limit (the producer's too).
constexpr long kBoxLimit = 20000000;

Matrix read_basis(Context& context, const Json& node, const std::string& path) {
    if (!node.is_array() || node.size() != 3) context.malformed(path, "expected three rows");
    Matrix basis;
    for (int i = 0; i < 3; ++i) {
        const std::string row_path = path + "[" + std::to_string(i) + "]";
        if (!node[i].is_array() || node[i].size() != 3) context.malformed(row_path, "expected three entries");
        for (int j = 0; j < 3; ++j) {
            // rational_at reads a key of an object: wrap the entry so that it is validated alike.
            const Json holder{{std::to_string(j), node[i][j]}};
            basis[i][j] = context.rational_at(holder, std::to_string(j), row_path);
        }
    }
    return basis;
}

Vector cross(const Vector& u, const Vector& w) {
    return {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
}

mpq_class dot(const Vector& u, const Vector& w) { return u[0] * w[0] + u[1] * w[1] + u[2] * w[2]; }

Vector combination(const Matrix& basis, const Triple& t) {
    Vector v;
    for (int j = 0; j < 3; ++j) v[j] = t[0] * basis[0][j] + t[1] * basis[1][j] + t[2] * basis[2][j];
    return v;
}

// The basis reduction (NOTES.md 5.6): proof.reduction = {transform U, reduced_basis R}, U with
// integer entries and det U = +-1 and R = U B exactly, so that R spans the lattice of B and the
// enumeration may run on R; a vector with coefficients t in R has coefficients t U in B. A file
// without the key enumerates B itself (U = identity).
struct Reduction {
    Matrix reduced;
    IntegerMatrix transform;
    Triple given(const Triple& t) const {
        Triple result{0, 0, 0};
        for (int j = 0; j < 3; ++j) {
            const mpz_class sum = t[0] * transform[0][j] + t[1] * transform[1][j] + t[2] * transform[2][j];
            if (!sum.fits_slong_p()) throw std::domain_error("coefficients in the given basis beyond 64 bits");
            result[j] = sum.get_si();
        }
        return result;
    }
};

Reduction replay_reduction(Context& context, const Json& proof, const Matrix& basis) {
    Reduction reduction{basis, {}};
    for (int i = 0; i < 3; ++i) reduction.transform[i][i] = 1;
    if (!proof.contains("reduction")) return reduction;
    const std::string path = "proof.reduction";
    const Json& node = context.member(proof, "reduction", "proof");
    const Json& transform = context.member(node, "transform", path);
    if (!transform.is_array() || transform.size() != 3) context.malformed(path + ".transform", "expected three rows");
    for (int i = 0; i < 3; ++i) {
        const std::string row = path + ".transform[" + std::to_string(i) + "]";
        if (!transform[i].is_array() || transform[i].size() != 3) context.malformed(row, "expected three integers");
        for (int j = 0; j < 3; ++j) {
            if (!transform[i][j].is_number_integer()) context.malformed(row, "expected integers");
            reduction.transform[i][j] = transform[i][j].get<long>();
        }
    }
    context.current_step = path;
    const mpz_class det = determinant(reduction.transform);
    context.require(det == 1 || det == -1, path + ".transform",
                    "det U = " + det.get_str() + ": not unimodular, so U B need not span the same lattice");
    reduction.reduced = read_basis(context, context.member(node, "reduced_basis", path), path + ".reduced_basis");
    context.require(reduction.reduced == product(reduction.transform, basis), path + ".reduced_basis",
                    "the reduced basis is not U B");
    return reduction;
}

Real norm_enclosure(const Vector& v, const Real& two_p, mpfr_prec_t precision) {
    return lattice_norm({rational(v[0], precision), rational(v[1], precision), rational(v[2], precision)}, two_p);
}

std::string basis_words(const Matrix& basis) {
    std::string words;
    for (int i = 0; i < 3; ++i)
        words += std::string(i ? ", " : "") + "(" + exact_text(basis[i][0]) + ", " + exact_text(basis[i][1]) + ", " +
                 exact_text(basis[i][2]) + ")";
    return words;
}

std::string check_lattice_check(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const Json& proof = context.member(document, "proof", "");
    const mpfr_prec_t precision = context.precision();

    const Matrix basis = read_basis(context, context.member(data, "basis", "claim.data"), "claim.data.basis");
    const mpq_class p = context.rational_at(data, "p", "claim.data");
    context.require(read_basis(context, context.member(inputs, "basis", "inputs"), "inputs.basis") == basis, "inputs.basis",
                    "the input basis differs from the claim's");
    context.require(context.rational_at(inputs, "p", "inputs") == p, "inputs.p", "the input p differs from the claim's");
    context.require(p >= mpq_class(1, 2), "inputs.p", "the packing criterion needs p >= 1/2 (a convex superball)");
    const Json& packing_node = context.member(data, "packing", "claim.data");
    if (!packing_node.is_boolean()) context.malformed("claim.data.packing", "expected true or false");
    const bool packing = packing_node.get<bool>();
    if (context.string_at(proof, "kind", "proof") != "enumeration") context.malformed("proof.kind", "expected \"enumeration\"");

    // The enumeration runs on the reduced basis R = U B (rows r_i), the same lattice.
    const Reduction reduction = replay_reduction(context, proof, basis);
    const Matrix& rows = reduction.reduced;

    // The coefficient bound, exactly: a_i = (r_j x r_k) . v / det and |(r_j x r_k) . v| <=
    // ||r_j x r_k||_1 ||v||_inf <= ||r_j x r_k||_1 ||v||_(2p).
    const mpq_class det = dot(rows[0], cross(rows[1], rows[2]));
    context.require(det != 0, "claim.data.basis", "the basis is singular");
    const Json& bound_data = context.member(proof, "bound_data", "proof");
    check_encloses(context, context.member(bound_data, "determinant", "proof.bound_data"), "proof.bound_data.determinant",
                   rational(abs(det), precision));
    const Json& cross_norms = context.member(bound_data, "cross_norms", "proof.bound_data");
    if (!cross_norms.is_array() || cross_norms.size() != 3) context.malformed("proof.bound_data.cross_norms", "expected three intervals");
    const Triple stated_bound = read_triple(context, context.member(proof, "coefficient_bound", "proof"), "proof.coefficient_bound");
    Triple bound;
    long boxes = 1;  // triples in the checker's box (the limit is checked before each product)
    for (int i = 0; i < 3; ++i) {
        const Vector normal = cross(rows[(i + 1) % 3], rows[(i + 2) % 3]);
        const mpq_class l1 = abs(normal[0]) + abs(normal[1]) + abs(normal[2]);
        const std::string path = "proof.bound_data.cross_norms[" + std::to_string(i) + "]";
        check_encloses(context, cross_norms[i], path, rational(l1, precision));
        mpz_class n;
        const mpq_class limit = 2 * l1 / abs(det);
        mpz_fdiv_q(n.get_mpz_t(), limit.get_num_mpz_t(), limit.get_den_mpz_t());
        context.require(n <= kBoxLimit && boxes * (2 * n + 1) <= kBoxLimit, "proof.coefficient_bound",
                        "the coefficient box is too large to enumerate");
        bound[i] = n.get_si();
        boxes *= 2 * bound[i] + 1;
        context.require(stated_bound[i] >= bound[i], "proof.coefficient_bound",
                        "the stated bound " + std::to_string(stated_bound[i]) + " on coefficient " + std::to_string(i) +
                            " is below the checker's floor(2 ||e_j x e_k||_1 / |det|) = " + std::to_string(bound[i]));
    }

    // The listed candidates, by triple.
    const Json& candidates = context.member(proof, "candidates", "proof");
    if (!candidates.is_array()) context.malformed("proof.candidates", "expected an array");
    std::map<Triple, std::size_t> listed;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        const std::string path = "proof.candidates[" + std::to_string(k) + "]";
        const Triple t = read_triple(context, context.member(candidates[k], "coefficients", path), path + ".coefficients");
        context.require(canonical(t), path, "not one nonzero triple per +-pair");
        context.require(listed.emplace(t, k).second, path, "listed twice");
    }

    const mpq_class two_p_exact = 2 * p;
    const Real two = integer(2, precision);
    const Real two_p = rational(two_p_exact, precision);
    std::set<Triple> contacts;
    long below = 0;
    // Decides one listed candidate: its norm enclosure must contain the checker's, and its
    // status must be the checker's (or undecided beside a witness).
    auto decide = [&](const Triple& t, std::size_t index) {
        const Vector v = combination(rows, t);
        const std::string path = "proof.candidates[" + std::to_string(index) + "]";
        context.current_step = path;
        const Json& entry = candidates[index];
        const Real norm = norm_enclosure(v, two_p, precision);
        check_encloses(context, context.member(entry, "norm", path), path + ".norm", norm);
        std::string status;
        if (less(norm, two)) {
            status = "below";
            ++below;
            context.require(!packing, path, "the vector " + triple_text(t) + " has norm " + text(norm) +
                                                " < 2: the lattice is not a packing");
        } else if (less(two, norm)) {
            status = "above";
        } else if (norm_is_exactly_two(v, two_p_exact)) {
            status = "contact";
            contacts.insert(t);
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
    };
    std::set<Triple> in_box;
    for (long a = 0; a <= bound[0]; ++a)
        for (long b = (a == 0 ? 0 : -bound[1]); b <= bound[1]; ++b)
            for (long c = (a == 0 && b == 0 ? 1 : -bound[2]); c <= bound[2]; ++c) {
                const Triple t{a, b, c};
                const Vector v = combination(rows, t);
                if (abs(v[0]) > 2 || abs(v[1]) > 2 || abs(v[2]) > 2) continue;  // norm >= max |v_j| > 2
                const auto found = listed.find(t);
                context.require(found != listed.end(), "proof.candidates",
                                "the candidate " + triple_text(t) + " (all coordinates at most 2 in size) is missing");
                decide(t, found->second);
                in_box.insert(t);
            }
    for (const auto& [t, index] : listed)
        if (!in_box.count(t)) decide(t, index);
    check_p_decimal(context, inputs, p);  // after the proof, which names a wrong p first

    context.current_step = "claim.data";
    if (packing) {
        const Json& count = context.member(data, "contacts", "claim.data");
        if (!count.is_number_integer()) context.malformed("claim.data.contacts", "expected an integer");
        context.require(count.get<long>() == 2 * static_cast<long>(contacts.size()), "claim.data.contacts",
                        "the checker finds " + std::to_string(2 * contacts.size()) + " contacts");
        const Json& vectors = context.member(data, "contact_vectors", "claim.data");
        if (!vectors.is_array()) context.malformed("claim.data.contact_vectors", "expected an array");
        // Stated in the given basis: the checker's contacts t (in R) are t U there.
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
        // The proof's list of decided contacts, each with its exact vector.
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
        // The sentence: the contacts verified, and |det B| exactly.
        return "The lattice with basis rows " + basis_words(basis) + " at p = " + exact_text(p) +
               " is a packing of the superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1 with " + std::to_string(count.get<long>()) +
               " contacts (every nonzero lattice vector has 2p-norm >= 2, with equality exactly for the contact vectors), " +
               "of packing density V_sb(p) / |det B| with |det B| = " + exact_text(abs(det)) + ".";
    } else {
        context.require(below > 0, "claim.data.packing", "no candidate has norm < 2, yet the claim says not a packing");
        const Json& witness = context.member(data, "witness", "claim.data");
        const Triple t = read_triple(context, context.member(witness, "coefficients", "claim.data.witness"),
                                     "claim.data.witness.coefficients");
        context.require(t != Triple{0, 0, 0}, "claim.data.witness", "the zero vector is no witness");
        const Real norm = norm_enclosure(combination(basis, t), two_p, precision);
        const Real stated = proved_enclosure(context, context.member(witness, "norm", "claim.data.witness"),
                                             "claim.data.witness.norm", norm);
        context.require(less(norm, two), "claim.data.witness", "the witness norm " + text(norm) + " is not certainly < 2");
        return "The lattice with basis rows " + basis_words(basis) + " at p = " + exact_text(p) +
               " is not a packing of the superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1: the lattice vector " + triple_text(t) +
               " has 2p-norm in " + enclosure_words(stated) + " < 2.";
    }
}

const ClaimKindRegistration registration("lattice-check", check_lattice_check);

}  // namespace

}  // namespace superpack_checker
