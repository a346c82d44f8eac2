// Claim kind "family-lattice-check" (written by `superpack check-lattice --family F --p P
// --certificate FILE`): the lattice of family F at an exact p is a packing with N contacts, or
// is not one (a witness vector of 2p-norm < 2). The proof has two parts: the proof of the
// family's parameters (the same tree as a family-lattice certificate, replayed by
// replay_family_parameters) and the enumeration, which the checker redoes itself over its own
// interval basis (family_verdict.hpp). Contacts are decided by the family's unit equations
// (equations_audit.hpp), never by evaluating a norm that is exactly 2.
//
// Keys read: claim.data {family, p, verdict, contacts, contact_vectors | witness, contact_pairs
// (S6 only)}; inputs
// {family, p, p_decimal}; proof {kind, parameters, lattice}.
#include "checker/claims/family_verdict.hpp"
#include "checker/claims/literature.hpp"
#include "checker/core/render.hpp"

namespace superpack_checker {

namespace {

std::string check_family_lattice_check(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const Json& proof = context.member(document, "proof", "");
    const std::string family = read_family(context, data, inputs);
    const mpq_class p = context.rational_at(data, "p", "claim.data");
    context.require(context.rational_at(inputs, "p", "inputs") == p, "inputs.p", "the input p differs from the claim's");
    require_family_domain(context, family, p, p, "inputs.p");
    check_family_definition(context, family, data);
    if (context.string_at(proof, "kind", "proof") != "family-lattice-check")
        context.malformed("proof.kind", "expected \"family-lattice-check\"");
    const Real p_interval = rational(p, context.precision());
    const FamilyParameters replayed = replay_family_parameters(
        context, family, context.member(proof, "parameters", "proof"), "proof.parameters", p_interval, "inputs.p");
    const FamilyVerdict verdict =
        check_family_verdict(context, lattice_forms(family), replayed.symbols, p_interval, context.string_at(data, "verdict", "claim.data"),
                             data, "claim.data", context.member(proof, "lattice", "proof"), "proof.lattice");
    check_p_decimal(context, inputs, p);
    // O1 overlapping on (1/2, p*_o) (p < p*_o is part of the parameter proof) is the erratum.
    const bool refutes_o1 = family == "O1" && !verdict.packing && p > mpq_class(1, 2);
    return "At p = " + exact_text(p) + ", " + lattice_words(family) + " " + verdict_words(verdict) + "." +
           (refutes_o1 ? refutation_words(o1_packs) : "");
}

const ClaimKindRegistration registration("family-lattice-check", check_family_lattice_check);

}  // namespace

}  // namespace superpack_checker
