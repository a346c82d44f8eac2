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

#include "superpack/arith/exact.hpp"
#include "superpack/geometry/lattice_basis.hpp"
#include "superpack/geometry/superball.hpp"
#include "superpack/arith/enclosure_json.hpp"

namespace superpack {

enum class Verdict { admissible, overlapping, undecided };
const char* to_string(Verdict verdict);

using Coefficients = std::array<long, 3>;

template <class I>
struct LatticeVector {
    Coefficients coefficients;  // v = a e1 + b e2 + c e3
    std::array<I, 3> vector;
    I norm;                     // ||v||_(2p), over the whole p interval
};

template <class I>
struct LatticeCheck {
    Verdict verdict = Verdict::undecided;
    std::string reason;
    std::optional<I> min_norm;                   // min over nonzero lattice vectors of ||v||_(2p)
    std::vector<Coefficients> contact_vectors;   // proved norm exactly 2; v and -v both listed
    std::vector<LatticeVector<I>> near_contacts; // norm enclosure holds 2, not proved equal (one per +-pair)
    std::optional<LatticeVector<I>> witness;     // norm certainly < 2 (when overlapping)
    Coefficients coefficient_bound{};            // |a| <= N[0], |b| <= N[1], |c| <= N[2]
    std::vector<LatticeVector<I>> evaluated;     // every candidate whose norm was enclosed (one per +-pair)
    long excluded_by_max_norm = 0;               // candidates with a coordinate certainly > 2 in size
    std::size_t contacts() const { return contact_vectors.size(); }
};

// True when the triple is proved to have norm exactly 2 (by an identity of the family or an
// exact evaluation). Called only for candidates whose norm enclosure contains 2.
using ContactProof = std::function<bool(const Coefficients&)>;

// The core check. p may be a wide interval (an audit piece) and the basis entries wide boxes:
// the verdict then holds for every p in the piece and every basis in the boxes. Requires
// p >= 1/2 (throws InputError when p is not certainly >= 1/2) and a certainly nonsingular basis
// (otherwise the verdict is undecided with that reason).
template <class I>
LatticeCheck<I> check_lattice(const Basis<I>& basis, const I& p, const ContactProof& proved_contact);

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

// Check of an exact basis at an exact p >= 1/2. Contacts are decided exactly where possible:
// by rational arithmetic when 2p is an integer, and for vectors whose nonzero coordinates share
// one absolute value a (k of them) by the exact test k (a/2)^(2p) = 1 with 2p = m/n, i.e.
// (a/2)^m = k^(-n). Every other candidate whose enclosure holds 2 is a near contact.
LatticeCheck<DInterval> check_exact_lattice(const Basis<Rational>& basis, const Rational& p, const DoubleField& field);
LatticeCheck<Ball> check_exact_lattice(const Basis<Rational>& basis, const Rational& p, const BallField& field);

template <class I>
Json lattice_check_json(const LatticeCheck<I>& check, bool with_evaluated);
Json coefficients_json(const Coefficients& c);

}  // namespace superpack
