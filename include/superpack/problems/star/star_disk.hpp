// Dense lattice packings of the concave superdisk K = {|x|^(2p) + |y|^(2p) <= 1}, 0 < p < 1/2
// (NOTES.md 13.8): a floating-point search, and each find certified by the star-body test.
//
// The certificate rests on one reduction. A plane lattice L with basis rows u, w packs K iff the
// space lattice with rows (u, 0), (w, 0), (0, 0, 2) packs the superball K3 at the same p: for a
// vector (v, 0) the interiors of K3 and K3 + (v, 0) meet iff those of K and K + v do (a common
// interior point keeps both g < 1 when its third coordinate is set to 0, and its plane section is
// K's), and every vector with third coordinate of size >= 2 parts the cubes [-1, 1]^3. So the
// space lattice goes to check_exact_lattice, whose star test (geometry/star_lattice.cpp) proves or
// refutes it whatever the guess was; phi = A(p) / |det(u, w)| with A the area of K.
//
// No optimality is claimed: Fejes Toth's theorem (the densest packing of a centrally symmetric
// convex disk is a lattice packing) and the inscribed-hexagon reduction of problems/superdisk/superdisk.hpp
// both need convexity.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "superpack/arith/outcome.hpp"
#include "superpack/geometry/lattice.hpp"

namespace superpack {

using PlaneBasis = std::array<std::array<Rational, 2>, 2>;

template <class I>
struct StarDiskLattice {
    I area, insertion_phi;  // A, and A / 2 (the diamond lattice, below)
    Outcome status = Outcome::undecided;  // proved: a certified packing; else the reason says why not
    std::string reason;
    std::string start;  // where the search found it
    PlaneBasis basis{};
    std::optional<I> phi;  // A / |det(u, w)| when proved
    long candidates_checked = 0;  // lattice vectors given to the star test
};

// The lattice with rows (u, 0), (w, 0), (0, 0, 2) in the exact star test at p.
LatticeCheck<DInterval> check_plane_star_lattice(const PlaneBasis& basis, const Rational& p, const DoubleField& field);
LatticeCheck<Ball> check_plane_star_lattice(const PlaneBasis& basis, const Rational& p, const BallField& field);

// The densest certified lattice superpack finds for 0 < p < 1/2 (throws InputError otherwise):
// the search starts from the diamond lattice (1, 1), (1, -1) (K lies in the square |x| + |y| <= 1,
// which tiles the plane with that lattice: the analogue of the paper's insertion, phi = A / 2), the
// square lattice 2Z^2, the pinwheel lattices u = (1 + r(h), h), w = (-h, 1 + r(h)) with
// r(h) = (1 - h^(2p))^(1/(2p)) (the tip of one disk against the arm of the next), and random
// bases; the four densest finds are made exact (scaled up by 1 + 2^-40) and checked.
StarDiskLattice<DInterval> best_star_disk_lattice(const Rational& p, const DoubleField& field);
StarDiskLattice<Ball> best_star_disk_lattice(const Rational& p, const BallField& field);

}  // namespace superpack
