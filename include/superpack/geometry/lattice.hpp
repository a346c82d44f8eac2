// Certified admissibility of a lattice packing of superballs (p >= 1/2): every nonzero lattice
// vector must have 2p-norm >= 2 (NOTES.md section 5, "Packing criterion"). The candidate
// vectors are enumerated in a coefficient box that provably holds every vector of norm <= 2
// (NOTES.md, "Completeness of the enumeration"), so the verdict covers the whole lattice.
#pragma once
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "superpack/arith/enclosure_json.hpp"
#include "superpack/arith/exact.hpp"
#include "superpack/arith/outcome.hpp"
#include "superpack/geometry/lattice_basis.hpp"
#include "superpack/geometry/lattice_reduction.hpp"
#include "superpack/geometry/star_overlap.hpp"
#include "superpack/geometry/superball.hpp"

namespace superpack {

// Is the lattice a packing (admissible for 2K)? proved: admissible; refuted: overlapping, with
// a witness vector of norm < 2. Printed as "admissible", "overlapping" or "undecided".
const char* packing_word(Outcome verdict);

using Coefficients = std::array<long, 3>;

template <class I>
struct LatticeVector {
    Coefficients coefficients;  // v = a e1 + b e2 + c e3 in the given basis
    Coefficients enumerated;    // the same in the basis the enumeration ran on (the reduced one)
    std::array<I, 3> vector;
    I norm;                     // ||v||_(2p), over the whole p interval
};

// The enumeration's limits (NOTES.md 5.2): triples in the coefficient box, prod (2 N_i + 1), and
// candidates kept (lattice vectors with every coordinate at most 2 in size, about 64 / |det|).
// Beyond either the check is undecided, with the count in its reason.
constexpr long enumeration_box_limit = 20000000;
constexpr std::size_t enumeration_candidate_limit = 1000000;

template <class I>
struct LatticeCheck {
    Outcome verdict = Outcome::undecided;
    std::string reason;
    std::optional<I> min_norm;                   // min over nonzero lattice vectors of ||v||_(2p)
    std::vector<Coefficients> contact_vectors;   // proved norm exactly 2; v and -v both listed
    std::vector<LatticeVector<I>> near_contacts; // norm enclosure holds 2, not proved equal (one per +-pair)
    std::optional<LatticeVector<I>> witness;     // norm certainly < 2 (when overlapping)
    // For a star body (check_star_lattice): the point of both interiors, K and K + witness.
    std::optional<StarOverlapWitness<I>> witness_point;
    Coefficients coefficient_bound{};            // |a| <= N[0], |b| <= N[1], |c| <= N[2]
    std::vector<LatticeVector<I>> evaluated;     // every candidate whose norm was enclosed (one per +-pair)
    long excluded_by_max_norm = 0;               // candidates with a coordinate certainly > 2 in size
    // An exact basis is enumerated in its LLL reduction: the transform and the reduced basis.
    // Contacts, witness and near contacts are in the given basis (coefficients); the box,
    // `enumerated` and every candidate's order are in the reduced one.
    std::optional<BasisReduction> reduction;
    std::size_t contacts() const { return contact_vectors.size(); }
};

// The complete enumeration (NOTES.md 5.2): visits one of v, -v for every nonzero lattice vector
// whose coordinates may all be at most 2 in size, in a coefficient box that provably holds them
// all (its bound goes to check.coefficient_bound, the vectors excluded inside it to
// check.excluded_by_max_norm). Returns false, with check.reason, when the basis may be singular
// or the box or the candidates exceed the limits above.
template <class I>
using CandidateVisitor = std::function<void(const Coefficients&, const std::array<I, 3>&)>;
template <class I>
bool for_each_candidate(const Basis<I>& basis, LatticeCheck<I>& check, const CandidateVisitor<I>& visit);

// True when the triple is proved to have norm exactly 2 (by an identity of the family or an
// exact evaluation). Called only for candidates whose norm enclosure contains 2.
using ContactProof = std::function<bool(const Coefficients&)>;

// The core check. p may be a wide interval (an audit piece) and the basis entries wide boxes:
// the verdict then holds for every p in the piece and every basis in the boxes. Requires
// 1/2 <= p <= 10^15 (throws InputError when p is not certainly in that range) and a certainly
// nonsingular basis (otherwise the verdict is undecided with that reason). The upper limit
// (NOTES.md 5.2): a vector with a coordinate 2 and another nonzero one has norm within
// 2 ln2 / (2p) of 2, below binary64's resolution beyond p ~ 10^14, and the 2p-th powers of
// coordinate enclosures near 2 overflow binary64 near p ~ 10^18.
template <class I>
LatticeCheck<I> check_lattice(const Basis<I>& basis, const I& p, const ContactProof& proved_contact);

// The check for a star body (p < 1/2, NOTES.md 13.2): the lattice is a packing iff the
// interiors of K and K + v are disjoint for every nonzero lattice vector v, and only v with every
// coordinate below 2 in size can fail (K lies in [-1, 1]^3): the candidates of for_each_candidate,
// each decided by star_overlap. refuted: a witness vector and a point of both interiors;
// undecided: the candidates whose test spent its budget are the near contacts. A candidate's
// "norm" is its gauge (a quasi-norm here: a gauge above 2 decides nothing). min_norm stays empty.
// Throws InputError for a convex body (2p >= 1: use check_lattice).
struct StarLatticeBudget {
    long first_boxes = 2000;    // each candidate's overlap test first gets this many boxes
    long total_boxes = 60000;   // the undecided ones then share what is left of this (about 1 s)
};
template <class I>
LatticeCheck<I> check_star_lattice(const Basis<I>& basis, const Superball& body, const StarLatticeBudget& budget = {});

// An exact basis "a,b,c; d,e,f; g,h,i" (decimals or fractions). Throws InputError when malformed
// or singular (determinant exactly 0).
Basis<Rational> parse_basis(const std::string& text);

template <class Field>
Basis<typename Field::Interval> enclose_basis(const Basis<Rational>& basis, const Field& field) {
    auto row = [&](int i) {
        return std::array<typename Field::Interval, 3>{field.rational(basis[i][0]), field.rational(basis[i][1]),
                                                       field.rational(basis[i][2])};
    };
    return Basis<typename Field::Interval>{{row(0), row(1), row(2)}};
}

// Check of an exact basis at an exact p > 0, enumerated in its exact LLL reduction (so that a
// skewed basis of a reasonable lattice has a small box); below p = 1/2 by check_star_lattice,
// whose witness point follows the witness's sign. Contacts are decided exactly
// (decide_norm_is_two, NOTES.md 5.3); a candidate whose enclosure holds 2 and which that test
// does not prove to have norm 2 is a near contact. Results are reported in the given basis.
LatticeCheck<DInterval> check_exact_lattice(const Basis<Rational>& basis, const Rational& p, const DoubleField& field);
LatticeCheck<Ball> check_exact_lattice(const Basis<Rational>& basis, const Rational& p, const BallField& field);

template <class I>
Json lattice_check_json(const LatticeCheck<I>& check, bool with_evaluated);
Json coefficients_json(const Coefficients& c);
// c or -c, whichever has its first nonzero entry positive (one triple per +-pair).
Coefficients representative(const Coefficients& c);
// {method, transform U (integer rows), reduced_basis U B (exact rationals)}.
Json reduction_json(const BasisReduction& reduction);

}  // namespace superpack
