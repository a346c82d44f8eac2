// The answer to a yes-or-no question that interval arithmetic decides: proved, refuted, or
// undecided at this precision. One vocabulary for every such question in superpack (is this
// point inside the body, is this lattice a packing, does this family's lattice exist, does a
// value agree with a printed one), so that "could not decide" is never merged with "no". Each
// question prints its own words (packing_word, agreement_word, the family status).
#pragma once

namespace superpack {

enum class [[nodiscard]] Outcome { proved, refuted, undecided };

}  // namespace superpack
