// Replaying the proof that fixes a family's parameters at p (a point, or an interval of p for
// the audit): the Newton box and root-free partition of s (C0, C1), a direct evaluation (O0),
// or the partition of the (q, s) box with the root of largest s (O1), or the partition of the
// (x, y, z) box with the one root with x, y, z > 0 and y < z (D14), or the Krawczyk leaf of the
// KKT point of Minkowski's six pairs (S6, superpack's own family). Shared by the claim kinds
// family-lattice, family-lattice-check and audit, so that each replays the same proof tree.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "checker/core/replay.hpp"
#include "checker/formulas/equations.hpp"
#include "checker/formulas/equations_audit.hpp"
#include "checker/formulas/triple.hpp"

namespace superpack_checker {

using NamedReals = std::vector<std::pair<std::string, Real>>;

struct FamilyParameters {
    NamedReals parameters;  // as a claim states them: s (C0, C1); c (O0); l, q, s (O1); x, y, z (D14);
                            // b00..b22, mu1..mu6 (S6)
    NamedReals symbols;     // every symbol of the basis (adds t for C0 and C1)
    Matrix3 basis;
};

// The family named in the claim, which the inputs must repeat, and a check that [lo, hi] lies
// in its domain (C0, C1: p >= 1; O0: 1/2 < p <= 1; O1: p >= 1/2; D14: 1/2 <= p <= 1; S6:
// ln3/ln4 < p < 1, the lower end certified on an enclosure of ln3/ln4), naming `path` if not.
std::string read_family(Context& context, const Json& data, const Json& inputs);
void require_family_domain(Context& context, const std::string& family, const mpq_class& lo, const mpq_class& hi,
                           const std::string& path);

// S6's definition, written again here from NOTES.md 4.2 (never read from a certificate): the
// six contact triples of Minkowski's configuration A3 in S6's basis, b1, b2, b3, b2 - b3,
// b1 - b3, b1 - b2, in the order of the multipliers mu1..mu6.
const std::vector<Triple>& s6_triples();
// What a claim states of the family's definition beside its name (claim.data): for S6 its
// "contact_pairs", which must equal s6_triples() (rejected at claim.data.contact_pairs[k]); the
// other families state nothing more.
void check_family_definition(Context& context, const std::string& family, const Json& data);
// The basis as exact linear forms and the unit equations of the family's contacts: family_forms
// for the published families and D14, kkt_forms(s6_triples()) for S6.
FamilyForms lattice_forms(const std::string& family);

// Replays the proof node at `path` for `family` at p. Rejects (naming the step) unless it
// proves the parameters. `p_path` is named when p itself is wrong (O1 needs p < ln3/ln4).
FamilyParameters replay_family_parameters(Context& context, const std::string& family, const Json& proof,
                                          const std::string& path, const Real& p, const std::string& p_path);

// Eq. (12) of O1 in the unknowns (q, s), with its Jacobian, for Krawczyk.
System octahedral_system(const Real& p);
// The D14 equations in (x, y, z), with their Jacobian.
System d14_system(const Real& p);

}  // namespace superpack_checker
