// The outcome of a root search on a box. Existence and uniqueness are separate facts (CAPD,
// IBEX): `existence` is set when the operator maps the box into its own interior (Brouwer /
// Krawczyk), `uniqueness` when the derivative (or the preconditioned Jacobian) is proved
// nonsingular on the box. A box is reported RootStatus::unique only when both hold.
// RootStatus::none means the box is proved to hold no root. Everything else is
// RootStatus::undecided, with a reason.
#pragma once

namespace superpack {

enum class [[nodiscard]] RootStatus { unique, none, undecided };

inline const char* to_string(RootStatus status) {
    switch (status) {
        case RootStatus::unique: return "unique";
        case RootStatus::none: return "none";
        case RootStatus::undecided: return "undecided";
    }
    return "undecided";
}

}  // namespace superpack
