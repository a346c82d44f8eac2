// Where the family densities cross, proved over whole ranges of p, and their slopes at the
// sphere point p = 1.
//
// phi(p) = V(p) / |det B(s(p), p)|. d/dp comes from the families' own templates evaluated
// with Jet<I> in p; for C0 and C1 the root s(p) of the contact equation f(s, p) = 0 moves
// with p, and the implicit function theorem gives ds/dp = -f_p / f_s over a whole p piece
// (s is certified over the piece by enclose_family_at). Every result keeps its proof data
// (each p piece with the enclosures that decide it) so that a checker can replay it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "superpack/arith/outcome.hpp"
#include "superpack/problems/families/families.hpp"

namespace superpack {

// phi and dphi/dp of C0, C1 or O0 for every p of an interval.
template <class I>
struct DensitySlope {
    Family family = Family::C0;
    Outcome status = Outcome::undecided;
    std::string message;
    std::vector<NamedValue<I>> parameters;  // s (C0, C1: the smallest positive root) or c (O0)
    std::optional<I> parameter_slope;       // ds/dp (C0, C1)
    std::optional<I> phi, slope;            // phi(p) and phi'(p) for every p in the interval
};

template <class I>
DensitySlope<I> enclose_density_slope(Family family, const I& p);
// The same for C0 or C1 from an enclosure s of s(p) for every p of the interval.
template <class I>
DensitySlope<I> cubic_density_slope(Family family, const I& p, const I& s);

// A cubic family certified once over a p piece: for every p in `piece` the smallest
// positive root s(p) is the only root in `root_box` (the Newton box of enclose_family_at,
// whose lower part [0, root_box) is proved root-free). For p inside the piece, s(p) is
// then refined by Newton in root_box alone, without redoing the root-free search.
template <class I>
struct PieceRoot {
    Family family;
    I piece;
    I root_box;
    I root;  // s(p) for every p of the piece
    I phi;   // phi(p) for every p of the piece
};
template <class I>
std::optional<PieceRoot<I>> certify_piece_root(Family family, const I& piece);
template <class I>
std::optional<I> smallest_root_within(const PieceRoot<I>& known, const I& p);

// Three-valued comparison of a certified enclosure with a claimed value.
// Does a certified value agree with a printed one? Printed as "agree", "disagree" or "undecided".
const char* agreement_word(Outcome agreement);

// A decimal printed as "d..." read two ways: truncated (the value lies between d and d plus
// one unit in its last place, away from zero) and rounded (within half a unit of d).
template <class I>
struct PrintedCheck {
    std::string printed;
    Outcome truncated = Outcome::undecided, rounded = Outcome::undecided;
};
template <class I>
PrintedCheck<I> check_printed(const I& x, const std::string& printed);
// Equal to the certified x? agree = the enclosures overlap, disagree = they are disjoint.
template <class I>
Outcome check_overlap(const I& x, const I& claim);

// One piece of [1, 10] in the proof that phi_C1 - phi_C0 has exactly one zero in (1, 10].
// Pieces are proved in binary64 intervals (exact double endpoints): the partition does not
// depend on --digits, only the refinement of the root does.
enum class PieceClaim { negative, positive, root, undecided };
const char* to_string(PieceClaim claim);

struct SignPiece {
    DInterval p;
    PieceClaim claim = PieceClaim::undecided;
    std::string reason;
    std::optional<DInterval> difference;  // an enclosure of g = phi_C1 - phi_C0 on the piece
    std::optional<DInterval> derivative;  // an enclosure of g' on the piece
};

template <class I>
struct CubicCrossover {
    bool certified = false;
    std::string message;  // why not, when not certified
    std::vector<SignPiece> pieces;  // a partition of [1, 10], in order
    int sign_left = 0, sign_right = 0;  // sign of g on (1, p*_c) and on (p*_c, 10]
    std::optional<NewtonResult<I>> newton;  // p*_c: unique in newton->initial_box (the root piece)
    std::optional<I> p, phi, phi_c0, phi_c1;
    // The p = 1 end: g(1) = 0 exactly (both lattices are FCC, NOTES.md); the slopes decide.
    std::optional<DensitySlope<I>> c0_at_1, c1_at_1;
};

CubicCrossover<DInterval> certify_cubic_crossover(const DoubleField& field, long digits);
CubicCrossover<Ball> certify_cubic_crossover(const BallField& field, long digits);

// Eq. (6): 2 (1 - 2^(1-2p))^(1/(2p)) - 1 = 0, and the meeting of O0 and O1 at its root.
template <class I>
struct OctahedralCrossover {
    bool certified = false;
    std::string message;
    std::optional<NewtonResult<I>> newton;  // the root of Eq. (6) itself, by interval Newton
    std::optional<I> ln3_over_ln4;          // the closed form (NOTES.md: Eq. 6 <=> 4^p = 3)
    Outcome closed_form = Outcome::undecided;  // does the root overlap ln3/ln4?
    std::vector<SignPiece> pieces;          // the sign of Eq. (6) on a partition of [1/2, 1]
    std::optional<I> p;                     // p*_o: the meet of the two enclosures
    FamilyLattice<I> o0{Family::O0};        // O0 at p*_o
    // O1 at p*_o is the limit q -> 0 of its Minkowski branch (a fold: Newton cannot
    // certify it there). At p*_o, (q, s) = (0, 1) solves Eq. (12) exactly since l = 1/2
    // (NOTES.md); these are the residuals of Eq. (12) there and the basis and density.
    std::vector<I> o1_residuals;
    std::optional<Basis<I>> o1_basis_at_root;
    std::optional<I> o1_determinant, o1_phi;
    // B_O0 = U B_O1 at p*_o with the integer U = [[2,-1,-1],[0,1,0],[1,0,-1]] (det -1):
    // the exact identity is in NOTES.md; this is its check on the enclosures (overlap).
    bool same_lattice = false;
    Outcome densities_meet = Outcome::undecided;
    std::optional<I> phi;  // phi*_o
};

OctahedralCrossover<DInterval> certify_octahedral_crossover(const DoubleField& field, long digits);
OctahedralCrossover<Ball> certify_octahedral_crossover(const BallField& field, long digits);

// The one-sided slopes of the maximal density at p = 1 and the paper's closed forms.
template <class I>
struct SphereSlopes {
    DensitySlope<I> c0, c1, o0;  // each family's branch at p = 1
    std::optional<I> a_minus, a_plus;
    std::string a_plus_family;   // the cubic family with the larger slope (densest for p -> 1+)
    std::optional<I> closed_minus, closed_plus;  // -(pi/(12 sqrt2)) [...] as printed in the paper
    Outcome minus_vs_closed = Outcome::undecided, plus_vs_closed = Outcome::undecided;
    PrintedCheck<I> minus_printed, plus_printed, closed_plus_printed;
};

SphereSlopes<DInterval> certify_sphere_slopes(const DoubleField& field);
SphereSlopes<Ball> certify_sphere_slopes(const BallField& field);

}  // namespace superpack
