#include "checker/claims/claim_parts.hpp"

namespace superpack_checker {

ClaimParts read_claim_parts(const Json& claim, Context& context, const std::string& kind, const std::string& p_path,
                            const std::string& why_above_half) {
    const Json& document = context.document();
    ClaimParts parts{context.member(claim, "data", "claim"), context.member(document, "inputs", ""),
                     context.member(document, "proof", ""), mpq_class()};
    parts.p = context.rational_at(parts.data, "p", "claim.data");
    context.require(context.rational_at(parts.inputs, "p", "inputs") == parts.p, "inputs.p", "the input p differs from the claim's");
    context.require(parts.p > mpq_class(1, 2), p_path, why_above_half);
    if (context.string_at(parts.proof, "kind", "proof") != kind) context.malformed("proof.kind", "expected \"" + kind + "\"");
    return parts;
}

}  // namespace superpack_checker
