// Claim kind "family-lattice-check" (written by `superpack check-lattice --family F --p P
// --certificate FILE`): the lattice of family F at an exact p is a packing with N contacts, or
// is not one (a witness vector of 2p-norm < 2). The proof has two parts: the proof of the
// family's parameters (the same tree as a family-lattice certificate, replayed by
// replay_family_parameters) and the enumeration, which the checker redoes itself over its own
// interval basis (family_verdict.hpp). Contacts are decided by the family's unit equations
// (equations_audit.hpp), never by evaluating a norm that is exactly 2.
#include "checker/family_verdict.hpp"

namespace superpack_checker {

namespace {

void check_family_lattice_check(const Json& claim, Context& context) {
    const Json& document = context.document();
    const Json& data = context.member(claim, "data", "claim");
    const Json& inputs = context.member(document, "inputs", "");
    const Json& proof = context.member(document, "proof", "");
    const std::string family = context.string_at(data, "family", "claim.data");
    const mpq_class p = context.rational_at(data, "p", "claim.data");
    context.require(context.string_at(inputs, "family", "inputs") == family, "inputs.family",
                    "the input family differs from the claim's");
    context.require(context.rational_at(inputs, "p", "inputs") == p, "inputs.p", "the input p differs from the claim's");
    const mpq_class half(1, 2);
    if (family == "C0" || family == "C1") context.require(p >= 1, "inputs.p", "outside the domain p >= 1 of " + family);
    if (family == "O0") context.require(p > half && p <= 1, "inputs.p", "outside the domain 1/2 < p <= 1 of O0");
    if (family == "O1") context.require(p >= half, "inputs.p", "outside the domain p >= 1/2 of O1");
    if (context.string_at(proof, "kind", "proof") != "family-lattice-check")
        context.malformed("proof.kind", "expected \"family-lattice-check\"");
    const Real p_interval = rational(p, context.precision());
    const FamilyParameters replayed = replay_family_parameters(
        context, family, context.member(proof, "parameters", "proof"), "proof.parameters", p_interval, "inputs.p");
    check_family_verdict(context, family_forms(family), replayed.symbols, p_interval, data, "claim.data",
                         context.member(proof, "lattice", "proof"), "proof.lattice");
}

const ClaimKindRegistration registration("family-lattice-check", check_family_lattice_check);

}  // namespace

}  // namespace superpack_checker
