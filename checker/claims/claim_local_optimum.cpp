// Claim kind "local-optimum" (written by `superpack best --certificate` when the critical
// lattice is certified locally optimal; NOTES.md 8.9 and 11.8): at an exact p > 1/2, the
// lattice whose basis B is the KKT point of min det B subject to ||c_i B||_(2p) = 2 for the
// stated contact triples c_1..c_m is admissible for 2K (a packing of the superball K) and a
// strict local minimiser of |det| among the admissible lattices near it. The replay, each step
// in the checker's own arithmetic and formulas (equations_kkt.hpp):
//   1. Krawczyk on the stored box of x = (B, mu) proves exactly one KKT point there
//      (kkt_point.hpp); the stated basis and multipliers must contain the checker's.
//   2. Every multiplier is certainly > 0 (strict complementarity: the critical cone is the
//      tangent space {d : A d = 0}). Then det B = (2/3) sum mu_i > 0 at the point (the trace of
//      the stationarity rows against B, with Euler's identity <v, grad n(v)> = n = 2).
//   3. H + rho A^T A is certainly positive definite (interval LDL^T on the root box; H the
//      Hessian of the Lagrangian in B, A the constraint Jacobian, rho the stated weight): so
//      d^T H d > 0 for every d != 0 with A d = 0, the second-order sufficient condition.
//   4. The lattice check on the root box (family_verdict.hpp, the interval-basis enumeration):
//      every lattice vector but +-c_i B has norm > 2, and +-c_i B have norm exactly 2 by the KKT
//      equations. So the point is admissible and no other constraint is active nearby.
//   5. volume, determinant and phi = V_sb(p) / |det B| contain the checker's.
//
// Keys read: claim.data {p, contact_pairs, basis, multipliers, verdict, contacts,
// contact_vectors, volume, determinant, phi}; inputs {p, p_decimal}; proof {kind, kkt {kind,
// status, box, root}, second_order {rho}, lattice {kind, coefficient_bound, contacts
// [{coefficients}]}}.

#include "checker/claims/claim_parts.hpp"
#include "checker/claims/family_verdict.hpp"
#include "checker/claims/literature.hpp"
#include "checker/core/render.hpp"
#include "checker/formulas/kkt_point.hpp"
#include "checker/formulas/positive_definite.hpp"

namespace superpack_checker {

namespace {

// Step 3 at the checker's root box: H + rho A^T A from the KKT Jacobian.
void check_second_order(Context& context, const Json& proof, const KktEquations& equations, const Box& root) {
    const std::string path = "proof.second_order";
    const Json& node = context.member(proof, "second_order", "proof");
    const mpq_class rho = context.rational_at(node, "rho", path);
    context.current_step = path;
    const Real weight = rational(rho, root[0].precision());
    const std::vector<std::vector<Real>> jacobian = equations.jacobian(root);
    std::vector<std::vector<Real>> m(9, std::vector<Real>(9, Real(root[0].precision())));
    for (std::size_t a = 0; a < 9; ++a)
        for (std::size_t b = 0; b <= a; ++b) {
            Real constraints(root[0].precision());
            for (std::size_t i = 9; i < jacobian.size(); ++i) constraints = constraints + jacobian[i][a] * jacobian[i][b];
            m[a][b] = jacobian[a][b] + weight * constraints;
        }
    const std::size_t pivot = first_unproved_pivot(m);
    context.require(pivot == 9, path + ".rho",
                    "H + rho A^T A with rho = " + rho.get_str() + " is not certainly positive definite (pivot " +
                        std::to_string(pivot) + " of its LDL^T may be <= 0): the second-order condition is not proved");
}

std::string basis_words(const std::array<std::array<Real, 3>, 3>& rows) {
    std::string words;
    for (int i = 0; i < 3; ++i)
        words += std::string(i ? ", " : "") + "(" + enclosure_words(rows[i][0]) + ", " + enclosure_words(rows[i][1]) + ", " +
                 enclosure_words(rows[i][2]) + ")";
    return words;
}

// The stated basis (claim.data.basis), row by row: each entry must hold the KKT point's.
// Returns the stated enclosures, for the sentence.
std::array<std::array<Real, 3>, 3> check_stated_basis(Context& context, const Json& data, const KktPoint& point) {
    const Json& basis = context.member(data, "basis", "claim.data");
    if (!basis.is_array() || basis.size() != 3) context.malformed("claim.data.basis", "expected three rows");
    std::array<std::array<Real, 3>, 3> stated_basis = point.basis;
    for (int i = 0; i < 3; ++i) {
        const std::string row = "claim.data.basis[" + std::to_string(i) + "]";
        if (!basis[i].is_array() || basis[i].size() != 3) context.malformed(row, "expected three intervals");
        for (int j = 0; j < 3; ++j)
            stated_basis[i][j] = proved_enclosure(context, basis[i][j], row + "[" + std::to_string(j) + "]", point.basis[i][j]);
    }
    return stated_basis;
}

// Strict complementarity: one stated multiplier per contact pair, each holding the KKT point's,
// which is certainly positive.
void check_multipliers(Context& context, const Json& data, const KktPoint& point, const std::vector<Triple>& contacts) {
    const std::size_t m = contacts.size();
    const Json& multipliers = context.member(data, "multipliers", "claim.data");
    if (!multipliers.is_array() || multipliers.size() != m)
        context.malformed("claim.data.multipliers", "expected one interval per contact pair");
    for (std::size_t i = 0; i < m; ++i) {
        const std::string path = "claim.data.multipliers[" + std::to_string(i) + "]";
        // The sentence says every multiplier is > 0: so must the stated enclosure (it holds the checker's).
        const Real stated = proved_enclosure(context, multipliers[i], path, point.multipliers[i]);
        context.require(positive(stated), path,
                        "the multiplier of the contact pair " + triple_text(contacts[i]) + " is not certainly positive: " +
                            text(stated));
    }
}

// Admissibility, with exactly the contacts +-c_i B: the lattice of the KKT point is a packing
// whose enumeration finds the contact pairs and no other contact.
void check_admissible(Context& context, const Json& data, const Json& proof, const KktPoint& point,
                      const std::vector<Triple>& contacts, const Real& p_interval) {
    const std::size_t m = contacts.size();
    if (context.string_at(data, "verdict", "claim.data") != "packing")
        context.malformed("claim.data.verdict", "a local optimum is a packing: expected \"packing\"");
    NamedReals symbols;
    const std::vector<std::string> names = kkt_symbols();
    for (std::size_t k = 0; k < 9; ++k) symbols.emplace_back(names[k], point.root[k]);
    const FamilyVerdict verdict = check_family_verdict(context, kkt_forms(contacts), symbols, p_interval, "packing", data,
                                                       "claim.data", context.member(proof, "lattice", "proof"), "proof.lattice");
    context.require(verdict.contacts == 2 * static_cast<long>(m), "claim.data.contacts",
                    "the enumeration finds " + std::to_string(verdict.contacts) + " contacts, not the 2 x " +
                        std::to_string(m) + " vectors +-c_i B of the contact pairs");
}

std::string check_local_optimum(const Json& claim, Context& context) {
    // At p = 1/2 the norm is piecewise linear (an octahedron): no second derivatives.
    const ClaimParts parts =
        read_claim_parts(claim, context, "local-optimum", "inputs.p", "local optimality by second derivatives needs p > 1/2");
    const Json &data = parts.data, &inputs = parts.inputs, &proof = parts.proof;
    const mpq_class& p = parts.p;
    const mpfr_prec_t precision = context.precision();
    const std::vector<Triple> contacts = read_contact_pairs(context, data, "contact_pairs", "claim.data");
    const std::size_t m = contacts.size();
    const Real p_interval = rational(p, precision);

    // 1. The KKT point, and the stated basis and multipliers around it.
    const KktPoint point = replay_kkt_point(context, contacts, context.member(proof, "kkt", "proof"), "proof.kkt", p_interval);
    context.current_step = "claim.data";
    const std::array<std::array<Real, 3>, 3> stated_basis = check_stated_basis(context, data, point);
    // 2. Strict complementarity.
    check_multipliers(context, data, point, contacts);
    // 3. Second order.
    const KktEquations equations{contacts, p_interval};
    check_second_order(context, proof, equations, point.root);
    // 4. Admissibility, with exactly the contacts +-c_i B.
    check_admissible(context, data, proof, point, contacts, p_interval);
    // 5. phi. det B > 0 at the point (step 2), so |det B| = det B there.
    context.current_step = "claim.data";
    const Real volume = superball_volume(p_interval);
    const Real det = determinant(point.basis);
    check_encloses(context, context.member(data, "volume", "claim.data"), "claim.data.volume", volume);
    check_encloses(context, context.member(data, "determinant", "claim.data"), "claim.data.determinant", det);
    const Real phi = proved_enclosure(context, context.member(data, "phi", "claim.data"), "claim.data.phi", volume / abs(det));
    check_p_decimal(context, inputs, p);  // after the proof, which names a wrong p first

    std::string triples;
    for (std::size_t i = 0; i < m; ++i) triples += std::string(i ? ", " : "") + triple_text(contacts[i]);
    return "At p = " + exact_text(p) + ", the lattice with basis rows in " + basis_words(stated_basis) +
           " (the only point in its box where det B is critical subject to ||c B||_(2p) = 2 for the contact triples c = " +
           triples + ") is admissible for 2K, K the superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1 (" + std::to_string(m) +
           " contact pairs: every nonzero lattice vector has 2p-norm >= 2, with equality exactly for +-c B), and a strict "
           "local minimiser of |det| among admissible lattices near it (all " + std::to_string(m) +
           " multipliers > 0, the second-order condition holds): a locally densest lattice packing of the superball, of "
           "packing density phi = V_sb(p) / |det B| in " + enclosure_words(phi) + " (claim.data.phi; " + volume_words + ").";
}

const ClaimKindRegistration registration("local-optimum", check_local_optimum);

}  // namespace

}  // namespace superpack_checker
