// What the claim kinds about a superball at one p > 1/2 (local-optimum, critical-lattice) read
// first: claim.data, inputs and proof, whose kind must be the claim's; p, which inputs.p must
// repeat; and p > 1/2, where the norm is smooth enough for the claim's derivatives.
#pragma once
#include <gmpxx.h>

#include <string>

#include "checker/verifier.hpp"

namespace superpack_checker {

struct ClaimParts {
    const Json& data;
    const Json& inputs;
    const Json& proof;
    mpq_class p;
};

// Rejects at `p_path` with `why_above_half` when p <= 1/2, at proof.kind when it is not `kind`.
ClaimParts read_claim_parts(const Json& claim, Context& context, const std::string& kind, const std::string& p_path,
                            const std::string& why_above_half);

}  // namespace superpack_checker
