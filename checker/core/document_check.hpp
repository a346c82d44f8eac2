// What every certificate gets after its claim kind has replayed the proof, in one walk over the
// whole document (the same for every claim kind):
//  - every object with a "decimal" is an exact interval {"lo", "hi", "decimal"}, and its decimal
//    must be the checker's rendering of the exact ends (render.hpp: decimal_field), else a
//    rejection at that decimal's path;
//  - every key must have been read by some step (Context records every value read); any other
//    key is rejected at its path as unknown. The head's description of the producer (tool,
//    version, commit, command, backend, digits, rounding_self_test.checks) is read here;
//  - last, claim.text must be the checker's rendering of the claim, else a rejection at
//    "claim.text" showing both.
#pragma once
#include <string>

#include "checker/verifier.hpp"

namespace superpack_checker {

void check_document(Context& context, const Json& document, const std::string& stated_text, const std::string& rendered_text);

}  // namespace superpack_checker
