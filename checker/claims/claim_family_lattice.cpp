// Claim kind "family-lattice" (written by `superpack density --certificate`): phi = V_sb(p) /
// |det B| of one family of Jiao, Stillinger and Torquato (2009) at an exact p, and whether the
// lattice is a packing. The parameter proof:
//   C0, C1: s is the smallest positive root of the contact equation: a Newton leaf and a
//           root-free partition of [0, lower end of the Newton box];
//   O0:     a direct evaluation (nothing to solve);
//   O1:     a partition of [0,1] x [-1,1] (all roots of the contact equations with q >= 0) into
//           root-free and one-root pieces; (q, s) is the root with the largest s, and p < ln3/ln4;
//   D14:    a partition of [0,1] x [-1,1]^2 with the one root on the branch;
//   S6:     the Krawczyk leaf of the KKT point of the checker's own six triples (claim.data.
//           contact_pairs must repeat them), ln3/ln4 < p < 1.
// The checker recomputes s (or q, s), the basis, the volume and phi in its own arithmetic and
// checks that each stated enclosure contains its own. The verdict is that of a
// family-lattice-check certificate (family_verdict.hpp): "packing" (the enumeration), or
// "overlapping" (a witness), or "undecided" (nothing proved about packing, unless phi is
// certainly above 1: then it is not one). Only a proved packing lets the sentence call phi a
// packing density.
//
// Keys read: claim.data {family, p, parameters, volume, determinant, phi, verdict, contacts,
// contact_vectors | witness, contact_pairs (S6 only)}; inputs {family, p, p_decimal}; proof {kind, parameters, lattice}.
#include "checker/claims/family_verdict.hpp"
#include "checker/claims/literature.hpp"
#include "checker/core/render.hpp"

namespace superpack_checker {

namespace {

// The stated phi, proved to contain the checker's V_sb / |det B|.
Real check_quantities(Context& context, const Json& data, const Matrix3& basis, const Real& p,
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
    return proved_enclosure(context, context.member(data, "phi", "claim.data"), "claim.data.phi", volume / abs(det));
}

std::string check_family_lattice(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const std::string family = read_family(context, data, inputs);
    const mpq_class p = context.rational_at(data, "p", "claim.data");
    context.require(context.rational_at(inputs, "p", "inputs") == p, "inputs.p", "the input p differs from the claim's");
    require_family_domain(context, family, p, p, "inputs.p");
    check_family_definition(context, family, data);
    const Real p_interval = rational(p, context.precision());
    const Json& proof = context.member(document, "proof", "");
    if (context.string_at(proof, "kind", "proof") != "family-lattice") context.malformed("proof.kind", "expected \"family-lattice\"");
    const FamilyParameters replayed = replay_family_parameters(
        context, family, context.member(proof, "parameters", "proof"), "proof.parameters", p_interval, "inputs.p");
    context.current_step = "claim.data";
    const Real phi = check_quantities(context, data, replayed.basis, p_interval, replayed.parameters);

    check_p_decimal(context, inputs, p);  // after the proof, which names a wrong p first
    const std::string verdict = context.string_at(data, "verdict", "claim.data");
    const Json& lattice = context.member(proof, "lattice", "proof");
    const std::string ratio = "V_sb(p) / |det B| in " + enclosure_words(phi) + " (claim.data.phi; " + volume_words + ")";
    const std::string lead = "At p = " + exact_text(p) + ", " + lattice_words(family) + " ";
    if (verdict == "undecided") {
        if (!lattice.is_null()) context.malformed("proof.lattice", "an undecided verdict has no lattice proof: expected null");
        // The stated phi holds the true one: above 1, no translates of the body can be disjoint.
        if (less(integer(1, context.precision()), phi))
            return lead + "has " + ratio + ", above 1, so it is not a packing (a packing has density at most 1), " +
                   "and this is not a packing density.";
        return lead + "has " + ratio + "; this certificate does not prove the lattice a packing, so this is not claimed " +
               "to be a packing density.";
    }
    const FamilyVerdict result =
        check_family_verdict(context, lattice_forms(family), replayed.symbols, p_interval, verdict, data, "claim.data", lattice, "proof.lattice");
    if (result.packing) return lead + verdict_words(result) + ", of packing density phi = " + ratio + ".";
    const bool refutes_o1 = family == "O1" && p > mpq_class(1, 2);
    return lead + verdict_words(result) + ", so its " + ratio + " is not a packing density." +
           (refutes_o1 ? refutation_words(o1_packs) : "");
}

const ClaimKindRegistration registration("family-lattice", check_family_lattice);

}  // namespace

}  // namespace superpack_checker
