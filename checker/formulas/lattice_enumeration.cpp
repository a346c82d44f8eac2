#include "checker/formulas/lattice_enumeration.hpp"

#include <set>
#include <stdexcept>

#include "checker/core/limits.hpp"
#include "checker/core/real.hpp"
#include "checker/core/render.hpp"

namespace superpack_checker {

namespace {

using Vector = RationalVector;
using Matrix = RationalMatrix;

// Triples in the coefficient box, prod (2 N_i + 1): the enumeration's limit (the producer's too).
constexpr long kBoxLimit = 20000000;

Vector cross(const Vector& u, const Vector& w) {
    return {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
}

mpq_class dot(const Vector& u, const Vector& w) { return u[0] * w[0] + u[1] * w[1] + u[2] * w[2]; }

}  // namespace

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

Vector combination(const Matrix& basis, const Triple& t) {
    Vector v;
    for (int j = 0; j < 3; ++j) v[j] = t[0] * basis[0][j] + t[1] * basis[1][j] + t[2] * basis[2][j];
    return v;
}

std::string basis_words(const Matrix& basis) {
    std::string words;
    for (int i = 0; i < 3; ++i)
        words += std::string(i ? ", " : "") + "(" + exact_text(basis[i][0]) + ", " + exact_text(basis[i][1]) + ", " +
                 exact_text(basis[i][2]) + ")";
    return words;
}

Triple Reduction::given(const Triple& t) const {
    Triple result{0, 0, 0};
    for (int j = 0; j < 3; ++j) {
        const mpz_class sum = t[0] * transform[0][j] + t[1] * transform[1][j] + t[2] * transform[2][j];
        if (!sum.fits_slong_p()) throw std::domain_error("coefficients in the given basis beyond 64 bits");
        result[j] = sum.get_si();
    }
    return result;
}

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
        for (int j = 0; j < 3; ++j)
            reduction.transform[i][j] = read_integer(context, transform[i][j], row + "[" + std::to_string(j) + "]",
                                                     -max_coefficient, max_coefficient, "max_coefficient");
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

LatticeClaim read_lattice_claim(Context& context, const Json& data, const Json& inputs) {
    LatticeClaim claim;
    claim.basis = read_basis(context, context.member(data, "basis", "claim.data"), "claim.data.basis");
    claim.p = context.rational_at(data, "p", "claim.data");
    context.require(read_basis(context, context.member(inputs, "basis", "inputs"), "inputs.basis") == claim.basis, "inputs.basis",
                    "the input basis differs from the claim's");
    context.require(context.rational_at(inputs, "p", "inputs") == claim.p, "inputs.p", "the input p differs from the claim's");
    const Json& packing = context.member(data, "packing", "claim.data");
    if (!packing.is_boolean()) context.malformed("claim.data.packing", "expected true or false");
    claim.packing = packing.get<bool>();
    return claim;
}

mpq_class replay_candidates(Context& context, const Json& proof, const Matrix& rows, const CandidateDecision& decide) {
    const mpfr_prec_t precision = context.precision();
    // The coefficient bound, exactly: a_i = (r_j x r_k) . v / det and |(r_j x r_k) . v| <=
    // ||r_j x r_k||_1 ||v||_inf, and a candidate has ||v||_inf <= 2 (a convex body: ||v||_inf <=
    // ||v||_(2p) <= 2; a star body lies in [-1, 1]^3).
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

    std::set<Triple> in_box;
    for (long a = 0; a <= bound[0]; ++a)
        for (long b = (a == 0 ? 0 : -bound[1]); b <= bound[1]; ++b)
            for (long c = (a == 0 && b == 0 ? 1 : -bound[2]); c <= bound[2]; ++c) {
                const Triple t{a, b, c};
                const Vector v = combination(rows, t);
                if (abs(v[0]) > 2 || abs(v[1]) > 2 || abs(v[2]) > 2) continue;  // the cubes [-1, 1]^3 and v + [-1, 1]^3 are apart
                const auto found = listed.find(t);
                context.require(found != listed.end(), "proof.candidates",
                                "the candidate " + triple_text(t) + " (all coordinates at most 2 in size) is missing");
                decide(t, found->second);
                in_box.insert(t);
            }
    for (const auto& [t, index] : listed)
        if (!in_box.count(t)) decide(t, index);
    return det;
}

}  // namespace superpack_checker
