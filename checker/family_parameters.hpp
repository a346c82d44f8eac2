// Replaying the proof that fixes a family's parameters at p (a point, or an interval of p for
// the audit): the Newton box and root-free partition of s (C0, C1), a direct evaluation (O0),
// or the partition of the (q, s) box with the root of largest s (O1), or the partition of the
// (x, y, z) box with the one root with x, y, z > 0 and y < z (D14). Shared by the claim kinds
// family-lattice, family-lattice-check and audit, so that each replays the same proof tree.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "checker/equations.hpp"
#include "checker/replay.hpp"

namespace superpack_checker {

using NamedReals = std::vector<std::pair<std::string, Real>>;

struct FamilyParameters {
    NamedReals parameters;  // as a claim states them: s (C0, C1); c (O0); l, q, s (O1); x, y, z (D14)
    NamedReals symbols;     // every symbol of the basis (adds t for C0 and C1)
    Matrix3 basis;
};

// The family named in the claim, which the inputs must repeat, and a check that [lo, hi] lies
// in its domain (C0, C1: p >= 1; O0: 1/2 < p <= 1; O1: p >= 1/2; D14: 1/2 <= p <= 1), naming
// `path` if not.
std::string read_family(Context& context, const Json& data, const Json& inputs);
void require_family_domain(Context& context, const std::string& family, const mpq_class& lo, const mpq_class& hi,
                           const std::string& path);

// Replays the proof node at `path` for `family` at p. Rejects (naming the step) unless it
// proves the parameters. `p_path` is named when p itself is wrong (O1 needs p < ln3/ln4).
FamilyParameters replay_family_parameters(Context& context, const std::string& family, const Json& proof,
                                          const std::string& path, const Real& p, const std::string& p_path);

// Eq. (12) of O1 in the unknowns (q, s), with its Jacobian, for Krawczyk.
System octahedral_system(const Real& p);
// The D14 equations in (x, y, z), with their Jacobian.
System d14_system(const Real& p);

}  // namespace superpack_checker
