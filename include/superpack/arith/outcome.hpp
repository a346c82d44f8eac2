// The answer to a yes-or-no question that interval arithmetic decides: proved, refuted, or
// undecided at this precision. One vocabulary for every such question in superpack (is this
// point inside the body, is this lattice a packing, does this family's lattice exist), so that
// "could not decide" is never merged with "no".
#pragma once

namespace superpack {

enum class [[nodiscard]] Outcome { proved, refuted, undecided };

inline const char* to_string(Outcome outcome) {
    switch (outcome) {
        case Outcome::proved: return "proved";
        case Outcome::refuted: return "refuted";
        case Outcome::undecided: return "undecided";
    }
    return "undecided";
}

}  // namespace superpack
