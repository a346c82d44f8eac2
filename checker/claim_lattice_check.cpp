// Claim kind "lattice-check" (written by `superpack check-lattice --basis ... --certificate`):
// the lattice with an exact basis is a packing of the superball at an exact p >= 1/2 with N
// contacts, or is not a packing (a witness of 2p-norm < 2). NOTES.md sections 5 and 8.
//
// The checker trusts no list in the file. It recomputes the coefficient bound exactly in
// rationals (Cramer and Hoelder: |a_i| <= floor(2 ||e_j x e_k||_1 / |det|)), enumerates every
// triple of that box itself, and for each one whose exact coordinates are all at most 2 in size
// (a larger coordinate already gives norm > 2) requires it to be listed, recomputes its norm
// enclosure in MPFI, and decides it: certainly > 2, certainly < 2, or norm exactly 2 by an
// exact rational test. Anything else is a rejection.
#include <map>
#include <set>

#include "checker/replay.hpp"
#include "checker/triple.hpp"

namespace superpack_checker {

namespace {

using Vector = std::array<mpq_class, 3>;
using Matrix = std::array<Vector, 3>;

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

mpq_class power(const mpq_class& x, long k) {
    mpq_class result = 1;
    for (long i = 0; i < k; ++i) result *= x;
    return result;
}

// ||v||_(2p) = 2 decided exactly (NOTES.md 5.3): in rationals when 2p = m is an integer, else
// when the k nonzero coordinates share one absolute value a, by (a/2)^m k^n = 1 (2p = m/n).
// False when neither test applies.
bool norm_is_exactly_two(const Vector& v, const mpq_class& two_p) {
    const mpz_class& m = two_p.get_num();
    const mpz_class& n = two_p.get_den();
    if (!m.fits_slong_p() || m > 64 || !n.fits_slong_p() || n > 64) return false;
    if (n == 1) {
        mpq_class sum = 0;
        for (const mpq_class& x : v) sum += power(abs(x), m.get_si());
        return sum == power(mpq_class(2), m.get_si());
    }
    mpq_class a = 0;
    long k = 0;
    for (const mpq_class& x : v) {
        if (x == 0) continue;
        if (k > 0 && abs(x) != a) return false;
        a = abs(x);
        ++k;
    }
    return k > 0 && power(a / 2, m.get_si()) * power(mpq_class(k), n.get_si()) == 1;
}

Real norm_enclosure(const Vector& v, const Real& two_p, const Real& inverse_two_p, mpfr_prec_t precision) {
    Real sum = integer(0, precision);
    for (const mpq_class& x : v) sum = sum + pow_abs(rational(x, precision), two_p);
    return pow_abs(sum, inverse_two_p);
}

void check_lattice_check(const Json& claim, Context& context) {
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

    // The coefficient bound, exactly: a_i = (e_j x e_k) . v / det and |(e_j x e_k) . v| <=
    // ||e_j x e_k||_1 ||v||_inf <= ||e_j x e_k||_1 ||v||_(2p).
    const mpq_class det = dot(basis[0], cross(basis[1], basis[2]));
    context.require(det != 0, "claim.data.basis", "the basis is singular");
    const Json& bound_data = context.member(proof, "bound_data", "proof");
    check_encloses(context, context.member(bound_data, "determinant", "proof.bound_data"), "proof.bound_data.determinant",
                   rational(abs(det), precision));
    const Json& cross_norms = context.member(bound_data, "cross_norms", "proof.bound_data");
    if (!cross_norms.is_array() || cross_norms.size() != 3) context.malformed("proof.bound_data.cross_norms", "expected three intervals");
    const Triple stated_bound = read_triple(context, context.member(proof, "coefficient_bound", "proof"), "proof.coefficient_bound");
    Triple bound;
    long boxes = 1;  // triples in the checker's box (at most 2001^3: no overflow)
    for (int i = 0; i < 3; ++i) {
        const Vector normal = cross(basis[(i + 1) % 3], basis[(i + 2) % 3]);
        const mpq_class l1 = abs(normal[0]) + abs(normal[1]) + abs(normal[2]);
        const std::string path = "proof.bound_data.cross_norms[" + std::to_string(i) + "]";
        check_encloses(context, cross_norms[i], path, rational(l1, precision));
        mpz_class n;
        const mpq_class limit = 2 * l1 / abs(det);
        mpz_fdiv_q(n.get_mpz_t(), limit.get_num_mpz_t(), limit.get_den_mpz_t());
        context.require(n <= 1000, "proof.coefficient_bound", "the coefficient box is too large to enumerate");
        bound[i] = n.get_si();
        boxes *= 2 * bound[i] + 1;
        context.require(stated_bound[i] >= bound[i], "proof.coefficient_bound",
                        "the stated bound " + std::to_string(stated_bound[i]) + " on coefficient " + std::to_string(i) +
                            " is below the checker's floor(2 ||e_j x e_k||_1 / |det|) = " + std::to_string(bound[i]));
    }

    context.require(boxes <= 20000000, "proof.coefficient_bound", "the coefficient box is too large to enumerate");

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
    const Real inverse_two_p = rational(1 / two_p_exact, precision);
    std::set<Triple> contacts;
    long below = 0;
    for (long a = 0; a <= bound[0]; ++a)
        for (long b = (a == 0 ? 0 : -bound[1]); b <= bound[1]; ++b)
            for (long c = (a == 0 && b == 0 ? 1 : -bound[2]); c <= bound[2]; ++c) {
                const Triple t{a, b, c};
                const Vector v = combination(basis, t);
                if (abs(v[0]) > 2 || abs(v[1]) > 2 || abs(v[2]) > 2) continue;  // norm >= max |v_j| > 2
                const auto found = listed.find(t);
                context.require(found != listed.end(), "proof.candidates",
                                "the candidate " + triple_text(t) + " (all coordinates at most 2 in size) is missing");
                const std::string path = "proof.candidates[" + std::to_string(found->second) + "]";
                context.current_step = path;
                const Json& entry = candidates[found->second];
                const Real norm = norm_enclosure(v, two_p, inverse_two_p, precision);
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
            }

    context.current_step = "claim.data";
    if (packing) {
        const Json& count = context.member(data, "contacts", "claim.data");
        if (!count.is_number_integer()) context.malformed("claim.data.contacts", "expected an integer");
        context.require(count.get<long>() == 2 * static_cast<long>(contacts.size()), "claim.data.contacts",
                        "the checker finds " + std::to_string(2 * contacts.size()) + " contacts");
        const Json& vectors = context.member(data, "contact_vectors", "claim.data");
        if (!vectors.is_array()) context.malformed("claim.data.contact_vectors", "expected an array");
        std::set<Triple> stated, distinct;  // distinct: no vector listed twice in place of another
        for (std::size_t k = 0; k < vectors.size(); ++k) {
            Triple t = read_triple(context, vectors[k], "claim.data.contact_vectors[" + std::to_string(k) + "]");
            distinct.insert(t);
            if (!canonical(t)) t = {-t[0], -t[1], -t[2]};
            stated.insert(t);
        }
        context.require(stated == contacts && distinct.size() == 2 * contacts.size() && vectors.size() == distinct.size(),
                        "claim.data.contact_vectors",
                        "the stated contact vectors differ from the checker's");
        // The proof's list of decided contacts, each with its exact vector.
        const Json& decided = context.member(proof, "contacts", "proof");
        if (!decided.is_array()) context.malformed("proof.contacts", "expected an array");
        std::set<Triple> listed_contacts;
        for (std::size_t k = 0; k < decided.size(); ++k) {
            const std::string path = "proof.contacts[" + std::to_string(k) + "]";
            const Triple t = read_triple(context, context.member(decided[k], "coefficients", path), path + ".coefficients");
            const Vector v = combination(basis, t);
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
    } else {
        context.require(below > 0, "claim.data.packing", "no candidate has norm < 2, yet the claim says not a packing");
        const Json& witness = context.member(data, "witness", "claim.data");
        const Triple t = read_triple(context, context.member(witness, "coefficients", "claim.data.witness"),
                                     "claim.data.witness.coefficients");
        context.require(t != Triple{0, 0, 0}, "claim.data.witness", "the zero vector is no witness");
        const Real norm = norm_enclosure(combination(basis, t), two_p, inverse_two_p, precision);
        check_encloses(context, context.member(witness, "norm", "claim.data.witness"), "claim.data.witness.norm", norm);
        context.require(less(norm, two), "claim.data.witness", "the witness norm " + text(norm) + " is not certainly < 2");
    }
}

const ClaimKindRegistration registration("lattice-check", check_lattice_check);

}  // namespace

}  // namespace superpack_checker
