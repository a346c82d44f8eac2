// Claim kind "family-lattice" (written by `superpack density --certificate`): the density
// phi = V_sb(p) / |det B| of one family of Jiao, Stillinger and Torquato (2009) at an exact p.
//   C0, C1: s is the smallest positive root of Eq. 2 / Eq. 9: a Newton leaf and a root-free
//           partition of [0, lower end of the Newton box];
//   O0:     a direct evaluation (nothing to solve);
//   O1:     a partition of [0,1] x [-1,1] (all roots of Eq. 12 with q >= 0) into root-free
//           and one-root pieces; (q, s) is the root with the largest s, and p < ln3/ln4.
// The checker recomputes s (or q, s), the basis, the volume and phi in its own arithmetic
// and checks that each stated enclosure contains its own.
#include "checker/family_parameters.hpp"

namespace superpack_checker {

namespace {

void check_quantities(Context& context, const Json& data, const Matrix3& basis, const Real& p,
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
    check_encloses(context, context.member(data, "phi", "claim.data"), "claim.data.phi", volume / abs(det));
}

void check_family_lattice(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const std::string family = read_family(context, data, inputs);
    const mpq_class p = context.rational_at(data, "p", "claim.data");
    context.require(context.rational_at(inputs, "p", "inputs") == p, "inputs.p", "the input p differs from the claim's");
    require_family_domain(context, family, p, p, "inputs.p");
    const Real p_interval = rational(p, context.precision());
    const Json& proof = context.member(document, "proof", "");
    const FamilyParameters replayed = replay_family_parameters(context, family, proof, "proof", p_interval, "inputs.p");
    context.current_step = "claim.data";
    check_quantities(context, data, replayed.basis, p_interval, replayed.parameters);
}

const ClaimKindRegistration registration("family-lattice", check_family_lattice);

}  // namespace

}  // namespace superpack_checker
