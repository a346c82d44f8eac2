// S6 over pieces of p (NOTES.md 4.2, "The audit"): the KKT point of the six triples followed
// from the point proof at p = 9/10 in both directions. On each piece P = [lo, hi], Krawczyk in
// the mean-value form in p (krawczyk_isolate_in_parameter) proves that one box holds exactly one
// KKT point for every p of P; at the end the piece shares with the piece before (towards 9/10),
// the root of the new box must lie in the box before, where the root at that end is unique, so
// both boxes hold the same branch.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "superpack/problems/guess/lattice_search.hpp"
#include "superpack/solve/krawczyk.hpp"

namespace superpack {

struct S6Branch {
    KktPoint guess;                  // floating point, at the last proved piece's midpoint
    std::vector<DInterval> box;      // the last proved box: the anchor's, then each piece's
    std::vector<DInterval> root;     // the tightened root in it
};

// The anchor: the point proof at exactly p = 9/10 (as `density --family S6 --p 0.9`). Nothing,
// with the reason in `failure`, if Krawczyk does not prove it.
std::optional<S6Branch> s6_anchor(std::string& failure);

struct S6Piece {
    RootStatus status = RootStatus::undecided;
    std::string reason;
    Rational p0;                     // the piece's midpoint, where the residual is taken
    std::vector<DInterval> box;      // one KKT point for every p of the piece
    std::vector<DInterval> root;     // its tightened enclosure over the piece
};

// The piece [lo, hi] next to the branch's last box at `shared` (lo going up, hi going down).
// On success the branch moves on to this piece.
S6Piece s6_piece(S6Branch& branch, const Rational& lo, const Rational& hi, const Rational& shared);

// Does `box` hold, at the exact point p, a unique KKT point lying in `previous`?
bool s6_linked(const std::vector<DInterval>& box, const std::vector<DInterval>& previous, const Rational& p);

}  // namespace superpack
