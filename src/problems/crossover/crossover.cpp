#include "superpack/arith/mpfr_bounds.hpp"
#include "superpack/problems/crossover/crossover.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "superpack/solve/guess.hpp"
#include "superpack/solve/partition.hpp"

namespace superpack {

namespace {

// |det B| for an interval or a Jet (the sign of det is read from its value).
template <class T>
std::optional<T> abs_determinant(const Basis<T>& basis) {
    const T det = determinant(basis);
    if (certainly_positive(value_of(det))) return det;
    if (certainly_negative(value_of(det))) return -det;
    return std::nullopt;
}

// phi = V(p) / |det B|.
template <class T>
std::optional<T> density_of(const T& p, const Basis<T>& basis) {
    const auto det = abs_determinant(basis);
    if (!det) return std::nullopt;
    return enclose_ball_volume(p, 3) / *det;
}

// s(p) as a Jet: the enclosure s and ds/dp = -f_p / f_s (implicit function theorem), or
// nothing when f_s may vanish.
template <class I>
std::optional<Jet<I>> root_jet(Family family, const I& p, const I& s) {
    const I f_s = cubic_equation(family, variable(s), constant(p)).derivative;
    const I f_p = cubic_equation(family, constant(s), variable(p)).derivative;
    if (contains_zero(f_s)) return std::nullopt;
    return Jet<I>{s, -f_p / f_s};
}

template <class I>
I interval_from(const I& like, double lo, double hi) {
    return from_doubles(like, lo, hi);
}

}  // namespace

template <class I>
DensitySlope<I> enclose_density_slope(Family family, const I& p) {
    DensitySlope<I> result;
    result.family = family;
    const Jet<I> p_jet = variable(p);
    if (family == Family::O1) throw InputError("enclose_density_slope: O1 is not supported (fold at p*_o)");
    if (family == Family::O0) {
        result.parameters = {{"c", octahedral_height(p)}};
        const auto phi = density_of(p_jet, o0_basis(p_jet));
        if (!phi) {
            result.message = "the sign of det B is not decided";
            return result;
        }
        result.phi = phi->value;
        result.slope = phi->derivative;
        result.status = Outcome::proved;
        return result;
    }
    // C0, C1: s(p) is certified (smallest positive root) for every p of the interval.
    const FamilyLattice<I> lattice = enclose_family_at(family, p);
    if (lattice.status != Outcome::proved) {
        result.message = lattice.message;
        return result;
    }
    result = cubic_density_slope(family, p, lattice.parameters.front().value);
    if (result.status == Outcome::proved) result.phi = *lattice.phi;
    return result;
}

template <class I>
DensitySlope<I> cubic_density_slope(Family family, const I& p, const I& s) {
    DensitySlope<I> result;
    result.family = family;
    const Jet<I> p_jet = variable(p);
    const auto s_jet = root_jet(family, p, s);
    if (!s_jet) {
        result.message = "f_s may vanish: the implicit function theorem does not apply";
        return result;
    }
    const I ds = s_jet->derivative;
    const auto phi = density_of(p_jet, cubic_basis(family, *s_jet, p_jet));
    if (!phi) {
        result.message = "the sign of det B is not decided";
        return result;
    }
    result.parameters = {{"s", s}};
    result.parameter_slope = ds;
    result.phi = phi->value;
    result.slope = phi->derivative;
    result.status = Outcome::proved;
    return result;
}

template <class I>
std::optional<PieceRoot<I>> certify_piece_root(Family family, const I& piece) {
    const FamilyLattice<I> lattice = enclose_family_at(family, piece);
    if (lattice.status != Outcome::proved || lattice.branches.empty()) return std::nullopt;
    return PieceRoot<I>{family, piece, lattice.branches.front().proof.piece.front(), lattice.parameters.front().value,
                        *lattice.phi};
}

template <class I>
std::optional<I> smallest_root_within(const PieceRoot<I>& known, const I& p) {
    if (!contains(known.piece, p)) return std::nullopt;
    if (contains(p, known.piece)) return known.root;
    auto equation = [&](const auto& s) { return cubic_equation(known.family, s, p); };
    // A narrow box around a guess first: a unique root there, inside root_box, is the one
    // root of root_box, hence s(p). Otherwise Newton on all of root_box.
    const double guess = guess_root([&](const auto& s) { return cubic_equation(known.family, s, mid_double(p)); },
                                    mid_double(known.root));
    const double radius = 1e-10 + 4 * width_upper(p);
    if (std::isfinite(guess) && contains(known.root_box, from_doubles(p, guess - radius, guess + radius))) {
        const I narrow = from_doubles(p, guess - radius, guess + radius);
        const NewtonResult<I> newton = newton_isolate(equation, narrow, 0.0, 200);
        if (newton.status == RootStatus::unique) return newton.box;
    }
    const NewtonResult<I> newton = newton_isolate(equation, known.root_box, 0.0, 200);
    if (newton.status != RootStatus::unique) return std::nullopt;
    return newton.box;
}

const char* agreement_word(Outcome agreement) {
    switch (agreement) {
        case Outcome::proved: return "agree";
        case Outcome::refuted: return "disagree";
        case Outcome::undecided: return "undecided";
    }
    return "undecided";
}

const char* to_string(PieceClaim claim) {
    switch (claim) {
        case PieceClaim::negative: return "negative";
        case PieceClaim::positive: return "positive";
        case PieceClaim::root: return "root";
        case PieceClaim::undecided: return "undecided";
    }
    return "undecided";
}

namespace {

// agree: x lies strictly inside (lo, hi); disagree: x lies strictly outside [lo, hi].
template <class I>
Outcome classify(const I& x, const I& lo, const I& hi) {
    if (certainly_less(lo, x) && certainly_less(x, hi)) return Outcome::proved;
    if (certainly_less(x, lo) || certainly_less(hi, x)) return Outcome::refuted;
    return Outcome::undecided;
}

}  // namespace

template <class I>
PrintedCheck<I> check_printed(const I& x, const std::string& printed) {
    const auto field = field_of(x);
    const Rational value = parse_rational(printed);
    const std::size_t point = printed.find('.');
    Rational unit(1);
    if (point != std::string::npos)
        for (std::size_t k = point + 1; k < printed.size(); ++k) unit /= 10;
    const bool negative = !printed.empty() && printed[0] == '-';
    PrintedCheck<I> result{printed};
    const Rational truncated_lo = negative ? Rational(value - unit) : value;
    const Rational truncated_hi = negative ? value : Rational(value + unit);
    result.truncated = classify(x, field.rational(truncated_lo), field.rational(truncated_hi));
    const Rational half = unit / 2;
    result.rounded = classify(x, field.rational(value - half), field.rational(value + half));
    return result;
}

template <class I>
Outcome check_overlap(const I& x, const I& claim) {
    I meet = x;
    return intersect(meet, x, claim) ? Outcome::proved : Outcome::refuted;
}

// ---- the cubic crossover -------------------------------------------------------------

namespace {

struct EvaluationFailed : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// g = phi_C1 - phi_C0 = V (1/|det B_C1| - 1/|det B_C0|) for every p of an interval inside
// a certified piece, as a value (T = I) or with g' (T = Jet<I>). V is computed once.
template <class T, class I>
T difference(const PieceRoot<I>& c0_root, const PieceRoot<I>& c1_root, const I& p) {
    const auto s0 = smallest_root_within(c0_root, p);
    const auto s1 = smallest_root_within(c1_root, p);
    if (!s0 || !s1) throw EvaluationFailed("s not refined inside its certified piece");
    std::optional<T> det0, det1;
    T p_scalar = [&] {
        if constexpr (std::is_same_v<T, I>) return p;
        else return variable(p);
    }();
    if constexpr (std::is_same_v<T, I>) {
        det0 = abs_determinant(cubic_basis(Family::C0, *s0, p));
        det1 = abs_determinant(cubic_basis(Family::C1, *s1, p));
    } else {
        const auto jet0 = root_jet(Family::C0, p, *s0), jet1 = root_jet(Family::C1, p, *s1);
        if (!jet0 || !jet1) throw EvaluationFailed("f_s may vanish: the implicit function theorem does not apply");
        det0 = abs_determinant(cubic_basis(Family::C0, *jet0, p_scalar));
        det1 = abs_determinant(cubic_basis(Family::C1, *jet1, p_scalar));
    }
    if (!det0 || !det1) throw EvaluationFailed("the sign of det B is not decided");
    const T volume = enclose_ball_volume(p_scalar, 3);
    return volume / *det1 - volume / *det0;
}

template <class I>
Jet<I> difference_jet(const PieceRoot<I>& c0_root, const PieceRoot<I>& c1_root, const I& p) {
    return difference<Jet<I>>(c0_root, c1_root, p);
}

template <class I>
I difference_value(const PieceRoot<I>& c0_root, const PieceRoot<I>& c1_root, const I& p) {
    return difference<I>(c0_root, c1_root, p);
}

// The crossover equation as newton_isolate wants it (a value at a point, a Jet on a box),
// for p inside a piece where both roots s are certified once.
template <class I>
struct CrossoverEquation {
    PieceRoot<I> c0_root, c1_root;
    I operator()(const I& p) const { return difference_value(c0_root, c1_root, p); }
    Jet<I> operator()(const Jet<I>& p) const { return difference_jet(c0_root, c1_root, p.value); }
};

int sign_of(PieceClaim claim) {
    return claim == PieceClaim::negative ? -1 : claim == PieceClaim::positive ? 1 : 0;
}

// Newton at the field's precision on a piece; true when it proves a unique root there.
template <class I>
bool refine_root(const I& like, double lo, double hi, long digits, CubicCrossover<I>& result) {
    const I box = interval_from(like, lo, hi);
    const double target = digits > 17 ? std::pow(10.0, -static_cast<double>(digits)) / 4 : 0.0;
    const auto c0_root = certify_piece_root(Family::C0, box);
    const auto c1_root = certify_piece_root(Family::C1, box);
    if (!c0_root || !c1_root) return false;
    try {
        NewtonResult<I> newton = newton_isolate(CrossoverEquation<I>{*c0_root, *c1_root}, box, target, 400);
        if (newton.status != RootStatus::unique || !contains(newton.initial_box, newton.box)) return false;
        result.newton = newton;
        return true;
    } catch (const EvaluationFailed&) {
        return false;
    }
}

// The partition is proved with 40-bit Arb balls: faster than binary64 intervals here (Arb
// exp/log/gamma without conversions), and away from p*_c |g| >> 2^-40, so the pieces are the
// same as at 53 or 64 bits (233 either way). The pieces have exact double endpoints, so they
// are reported as binary64 intervals.
DInterval outward_double(const Ball& x) {
    mpfr_t lo, hi;
    mpfr_init2(lo, 53);
    mpfr_init2(hi, 53);
    get_bounds(lo, hi, x);
    const DInterval result = from_doubles(DInterval(0.0), mpfr_get_d(lo, MPFR_RNDD), mpfr_get_d(hi, MPFR_RNDU));
    mpfr_clear(lo);
    mpfr_clear(hi);
    return result;
}

// The first pieces of the cubic partition: `count` pieces of equal width from left_end to
// right_end (a step of its own: the partition's start, apart from how a piece is decided).
std::vector<std::vector<DInterval>> first_cubic_pieces(double left_end, double right_end, int count) {
    std::vector<double> ends;
    for (int k = 0; k < count; ++k) ends.push_back(left_end + (right_end - left_end) * k / count);
    ends.push_back(right_end);
    std::vector<std::vector<DInterval>> first;
    for (std::size_t k = 1; k < ends.size(); ++k) first.push_back({interval_from(DInterval(0.0), ends[k - 1], ends[k])});
    return first;
}

// Decides the sign of g = phi_C1 - phi_C0 on each piece of the cubic partition. A class, not a
// lambda in certify_cubic_crossover_impl, because what it learns is carried from piece to piece
// (pieces are proved left to right: the sign of g at the next piece's left end, the number of
// root pieces) and each way of deciding a piece is then a named step.
template <class Field>
class CubicSignClassifier {
public:
    using I = typename Field::Interval;
    CubicSignClassifier(const Field& field, long digits, const Ball& like, double left_end, CubicCrossover<I>& result)
        : field_(field), digits_(digits), like_(like), left_end_(left_end), result_(result) {}

    Classification<SignPiece> classify(const std::vector<DInterval>& box) {
        const double a = box[0].lower(), b = box[0].upper();
        const Ball p = interval_from(like_, a, b);
        SignPiece piece{box[0], PieceClaim::undecided, "", std::nullopt, std::nullopt};
        const auto c0_root = certify_piece_root(Family::C0, p);
        const auto c1_root = certify_piece_root(Family::C1, p);
        if (!c0_root || !c1_root) return not_decided<SignPiece>("s not certified over the piece");
        // The direct enclosure first: it needs no derivative.
        const Ball direct = c1_root->phi - c0_root->phi;
        if (a != left_end_ && (certainly_negative(direct) || certainly_positive(direct))) {
            const int sign = certainly_negative(direct) ? -1 : 1;
            piece.difference = outward_double(direct);
            return record(piece, sign < 0 ? PieceClaim::negative : PieceClaim::positive, "g excludes 0 on the piece (direct)",
                          sign);
        }
        Jet<Ball> g{like_, like_};
        try {
            g = difference_jet(*c0_root, *c1_root, p);
        } catch (const EvaluationFailed& failure) {
            return not_decided<SignPiece>(failure.what());
        }
        piece.derivative = outward_double(g.derivative);
        // Monotone from a known end: g(a) <= 0 and g' < 0 give g < 0 on (a, b]; likewise > 0.
        if (left_known_ && certainly_negative(g.derivative) && left_sign_ <= 0) {
            piece.difference = outward_double(g.value);
            return record(piece, PieceClaim::negative,
                          "g(a) <= 0 (the piece to the left, or g(1) = 0) and g' < 0 on the piece", -1);
        }
        if (left_known_ && certainly_positive(g.derivative) && left_sign_ >= 0) {
            piece.difference = outward_double(g.value);
            return record(piece, PieceClaim::positive,
                          "g(a) >= 0 (the piece to the left, or g(1) = 0) and g' > 0 on the piece", 1);
        }
        return classify_by_mean_value(piece, p, g, *c0_root, *c1_root);
    }

    // The undecided leaf of a piece the partition gives up on: the sign at the next left end is lost.
    SignPiece give_up(const std::vector<DInterval>& box, const std::string& reason) {
        left_known_ = false;
        return SignPiece{box[0], PieceClaim::undecided, reason, std::nullopt, std::nullopt};
    }

    std::size_t root_pieces() const { return root_pieces_; }

private:
    // A decided piece: its claim, and the sign of g it proved at its right end for the next piece.
    Classification<SignPiece> record(SignPiece& piece, PieceClaim claim, const std::string& reason, int right_sign) {
        piece.claim = claim;
        piece.reason = reason;
        left_known_ = true;
        left_sign_ = right_sign;
        return decided(piece);
    }

    // The direct enclosure, and if it does not decide, the mean value form g(m) + g'(P)(P - m)
    // met with it; then interval Newton when g' excludes 0 (the piece may hold the root).
    Classification<SignPiece> classify_by_mean_value(SignPiece& piece, const Ball& p, const Jet<Ball>& g,
                                                     const PieceRoot<Ball>& c0_root, const PieceRoot<Ball>& c1_root) {
        const double a = piece.p.lower(), b = piece.p.upper();
        Ball value = g.value;
        if (contains_zero(value) && a != left_end_) try {
            const Ball middle = midpoint(p);
            const Ball centered = difference_value(c0_root, c1_root, middle) + g.derivative * (p - middle);
            if (!intersect(value, centered, g.value)) value = centered;
        } catch (const EvaluationFailed&) {
        }
        piece.difference = outward_double(value);
        if (a != left_end_ && (certainly_negative(value) || certainly_positive(value))) {
            const int sign = certainly_negative(value) ? -1 : 1;
            return record(piece, sign < 0 ? PieceClaim::negative : PieceClaim::positive,
                          "g excludes 0 on the piece (mean value form)", sign);
        }
        if (a != left_end_ && !contains_zero(g.derivative) && refine_root(field_.integer(0), a, b, digits_, result_)) {
            ++root_pieces_;
            return record(piece, PieceClaim::root, "interval Newton: exactly one zero of g in the piece (g' excludes 0)",
                          certainly_positive(g.derivative) ? 1 : -1);
        }
        return not_decided<SignPiece>("neither g nor g' decided");
    }

    const Field& field_;
    long digits_;
    Ball like_;
    double left_end_;
    CubicCrossover<I>& result_;
    std::size_t root_pieces_ = 0;
    // The sign of g at the left end of the next piece: g(1) = 0 exactly (NOTES.md: both
    // lattices are FCC); after a piece, the sign it proved at its right end. Unknown after an
    // undecided piece.
    bool left_known_ = true;
    int left_sign_ = 0;
};

// Whether the partition shows exactly one sign change of g, at its one root piece; sets the
// signs on either side, or the message saying why not (a step of its own: the proof's
// conclusion from the pieces).
template <class I>
bool one_sign_change(CubicCrossover<I>& result, std::size_t root_pieces) {
    std::size_t undecided = 0, root_index = result.pieces.size();
    for (std::size_t k = 0; k < result.pieces.size(); ++k) {
        if (result.pieces[k].claim == PieceClaim::undecided) ++undecided;
        if (result.pieces[k].claim == PieceClaim::root) root_index = k;
    }
    if (undecided > 0) {
        result.message = std::to_string(undecided) + " pieces of [1, 10] undecided";
        return false;
    }
    if (root_pieces != 1) {
        result.message = std::to_string(root_pieces) + " pieces with a certified zero of g (expected 1)";
        return false;
    }
    // On the root piece g' has one sign, so g changes sign at the root: -sign(g') to its
    // left and sign(g') to its right. Every other piece must carry the matching sign.
    const int rise = certainly_positive(*result.pieces[root_index].derivative) ? 1 : -1;
    bool consistent = true;
    for (std::size_t k = 0; k < result.pieces.size(); ++k) {
        if (k == root_index) continue;
        consistent = consistent && sign_of(result.pieces[k].claim) == (k < root_index ? -rise : rise);
    }
    if (!consistent) {
        result.message = "g has more than one sign change on [1, 10]";
        return false;
    }
    result.sign_left = -rise;
    result.sign_right = rise;
    return true;
}

// The densities of C0 and C1 at the certified crossover p*_c, which must meet, and the slopes
// at p = 1 (a step of its own: what is reported once the root is proved).
template <class Field>
void enclose_at_crossover(CubicCrossover<typename Field::Interval>& result, const Field& field) {
    using I = typename Field::Interval;
    result.p = result.newton->box;
    const FamilyLattice<I> c0 = enclose_family_at(Family::C0, *result.p);
    const FamilyLattice<I> c1 = enclose_family_at(Family::C1, *result.p);
    if (!c0.phi || !c1.phi) {
        result.message = "the densities at p*_c are not certified";
        return;
    }
    result.phi_c0 = *c0.phi;
    result.phi_c1 = *c1.phi;
    I phi = *c0.phi;
    if (!intersect(phi, *c0.phi, *c1.phi)) {
        result.message = "phi_C0 and phi_C1 at p*_c do not overlap";
        return;
    }
    result.phi = phi;
    result.c0_at_1 = enclose_density_slope(Family::C0, field.integer(1));
    result.c1_at_1 = enclose_density_slope(Family::C1, field.integer(1));
    result.certified = true;
}

}  // namespace

template <class Field>
CubicCrossover<typename Field::Interval> certify_cubic_crossover_impl(const Field& field, long digits) {
    using I = typename Field::Interval;
    CubicCrossover<I> result;
    const BallField partition_field{40};
    const Ball like = partition_field.integer(0);
    // 150 first pieces of width 0.06: enclose_family_at certifies s over each of them
    // (at width 0.12 its starting box reaches 0 and Newton fails on most).
    const double left_end = 1.0, right_end = 10.0;
    const int first_pieces = 150;
    const double min_width = 1e-9;
    const std::size_t max_pieces = 20000;
    const std::vector<std::vector<DInterval>> first = first_cubic_pieces(left_end, right_end, first_pieces);
    CubicSignClassifier<Field> classifier(field, digits, like, left_end, result);
    auto classify = [&](const std::vector<DInterval>& box) { return classifier.classify(box); };
    auto give_up = [&](const std::vector<DInterval>& box, const std::string& reason) {
        return classifier.give_up(box, reason);
    };
    result.pieces = partition(first, classify, give_up, SubdivisionLimits{min_width, max_pieces});
    if (!one_sign_change(result, classifier.root_pieces())) return result;
    enclose_at_crossover(result, field);
    return result;
}

CubicCrossover<DInterval> certify_cubic_crossover(const DoubleField& field, long digits) {
    return certify_cubic_crossover_impl(field, digits);
}
CubicCrossover<Ball> certify_cubic_crossover(const BallField& field, long digits) {
    return certify_cubic_crossover_impl(field, digits);
}

// ---- the octahedral crossover ------------------------------------------------------

namespace {

// Eq. (6): 2 c(p) - 1, c the O0 height.
template <class T>
T octahedral_equation(const T& p) {
    return constant_like(p, 2) * octahedral_height(p) - constant_like(p, 1);
}

// Sign of Eq. (6) on [a, b] by direct evaluation, bisecting until decided (at most about
// (b - a) / 1e-9 pieces; in practice a few dozen).
void octahedral_signs(double a, double b, std::vector<SignPiece>& pieces) {
    auto classify = [](const std::vector<DInterval>& box) -> Classification<SignPiece> {
        SignPiece piece{box[0], PieceClaim::undecided, "", std::nullopt, std::nullopt};
        const Jet<DInterval> value = octahedral_equation(variable(box[0]));
        piece.difference = value.value;
        piece.derivative = value.derivative;
        if (!certainly_negative(value.value) && !certainly_positive(value.value))
            return not_decided<SignPiece>("Eq. (6) not decided");
        piece.claim = certainly_negative(value.value) ? PieceClaim::negative : PieceClaim::positive;
        piece.reason = "Eq. (6) excludes 0 on the piece";
        return decided(piece);
    };
    auto give_up = [](const std::vector<DInterval>& box, const std::string& reason) {
        const Jet<DInterval> value = octahedral_equation(variable(box[0]));
        return SignPiece{box[0], PieceClaim::undecided, reason, value.value, value.derivative};
    };
    const std::vector<SignPiece> found = partition(std::vector<std::vector<DInterval>>{{interval_from(DInterval(0.0), a, b)}},
                                                   classify, give_up, SubdivisionLimits{1e-9, 1000000});
    pieces.insert(pieces.end(), found.begin(), found.end());
}

// The piece [1/2, lemma_end], whose sign comes from the lemma Eq. (6) <=> 4^p = 3 (NOTES.md),
// not from Eq. (6) itself, which nears 0^(1/(2p)) there (a step of its own: a different proof).
SignPiece octahedral_lemma_piece(double lemma_end) {
    const DInterval p = interval_from(DInterval(0.0), 0.5, lemma_end);
    SignPiece piece{p, PieceClaim::undecided, "", std::nullopt, std::nullopt};
    piece.difference = exp(p * log(DInterval(4.0))) - DInterval(3.0);
    const bool negative = certainly_negative(*piece.difference);
    piece.claim = negative ? PieceClaim::negative : PieceClaim::undecided;
    piece.reason = "sign of Eq. (6) = sign of 4^p - 3 for p > 1/2 (NOTES.md); 'difference' encloses 4^p - 3";
    return piece;
}

// The root piece [root_lo, root_hi], decided by the interval Newton run on it (a step of its
// own: the piece that holds the root).
template <class I>
SignPiece octahedral_root_piece(double root_lo, double root_hi, const NewtonResult<I>& newton) {
    SignPiece piece{interval_from(DInterval(0.0), root_lo, root_hi), PieceClaim::undecided, "", std::nullopt, std::nullopt};
    const bool unique = newton.status == RootStatus::unique && contains(newton.initial_box, newton.box);
    piece.derivative = octahedral_equation(variable(piece.p)).derivative;
    piece.claim = unique ? PieceClaim::root : PieceClaim::undecided;
    piece.reason = "interval Newton on Eq. (6) (at the working precision): " + newton.reason;
    return piece;
}

// Whether B_O0 = U B_O1 with U = [[2,-1,-1],[0,1,0],[1,0,-1]] (det U = -1) at p*_o: O0 and O1
// are one lattice there (a step of its own: the identity the crossover claims).
template <class Field>
bool o1_is_o0(const OctahedralCrossover<typename Field::Interval>& result, const Field& field) {
    using I = typename Field::Interval;
    const I zero = field.integer(0);
    const long unimodular[3][3] = {{2, -1, -1}, {0, 1, 0}, {1, 0, -1}};
    bool same = result.o0.basis.has_value();
    for (int i = 0; i < 3 && same; ++i)
        for (int k = 0; k < 3; ++k) {
            I entry = zero;
            for (int j = 0; j < 3; ++j) entry = entry + field.integer(unimodular[i][j]) * (*result.o1_basis_at_root)[j][k];
            same = same && check_overlap(entry, (*result.o0.basis)[i][k]) == Outcome::proved;
        }
    return same;
}

}  // namespace

template <class Field>
OctahedralCrossover<typename Field::Interval> certify_octahedral_crossover_impl(const Field& field, long digits) {
    using I = typename Field::Interval;
    // The root piece [25/32, 13/16] holds ln3/ln4 = 0.79248...; below 9/16 the sign comes
    // from the lemma Eq. (6) <=> 4^p = 3 (NOTES.md), where Eq. (6) itself nears 0^(1/(2p)).
    const double lemma_end = 9.0 / 16, root_lo = 25.0 / 32, root_hi = 13.0 / 16;
    const double target = digits > 17 ? std::pow(10.0, -static_cast<double>(digits)) / 4 : 0.0;
    OctahedralCrossover<I> result;
    result.newton = newton_isolate([](const auto& p) { return octahedral_equation(p); },
                                   interval_from(field.integer(0), root_lo, root_hi), target, 400);
    result.ln3_over_ln4 = log(field.integer(3)) / log(field.integer(4));
    const NewtonResult<I>& newton = *result.newton;
    result.pieces.push_back(octahedral_lemma_piece(lemma_end));
    octahedral_signs(lemma_end, root_lo, result.pieces);
    result.pieces.push_back(octahedral_root_piece(root_lo, root_hi, newton));
    octahedral_signs(root_hi, 1.0, result.pieces);
    result.closed_form = check_overlap(newton.box, *result.ln3_over_ln4);
    std::size_t roots = 0, wrong = 0;
    for (const SignPiece& piece : result.pieces) {
        if (piece.claim == PieceClaim::root) ++roots;
        const bool left = piece.p.upper() <= root_lo;
        if (piece.claim == PieceClaim::undecided) ++wrong;
        else if (piece.claim != PieceClaim::root && sign_of(piece.claim) != (left ? -1 : 1)) ++wrong;
    }
    if (roots != 1 || wrong != 0 || result.closed_form != Outcome::proved) {
        result.message = "the root of Eq. (6) on (1/2, 1] is not certified unique, or misses ln3/ln4";
        return result;
    }
    I p = newton.box;
    intersect(p, newton.box, *result.ln3_over_ln4);
    result.p = p;
    result.o0 = enclose_family_at(Family::O0, p);
    const I zero = field.integer(0), one = field.integer(1);
    result.o1_residuals = o1_equations(std::vector<I>{zero, one}, p);
    result.o1_basis_at_root = o1_basis(zero, one, p);
    result.o1_determinant = determinant(*result.o1_basis_at_root);
    result.o1_phi = enclose_ball_volume(p, 3) / abs(*result.o1_determinant);
    const bool same = o1_is_o0(result, field);
    result.same_lattice = same;
    bool residuals_vanish = true;
    for (const I& residual : result.o1_residuals) residuals_vanish = residuals_vanish && contains_zero(residual);
    if (!result.o0.phi) {
        result.message = "O0 is not certified at p*_o";
        return result;
    }
    result.densities_meet = check_overlap(*result.o0.phi, *result.o1_phi);
    I phi = *result.o0.phi;
    intersect(phi, *result.o0.phi, *result.o1_phi);
    result.phi = phi;
    result.certified = residuals_vanish && same && result.densities_meet == Outcome::proved;
    if (!result.certified) result.message = "O1 at (q, s) = (0, 1) does not match O0 at p*_o";
    return result;
}

// ---- the slopes at the sphere point --------------------------------------------------

template <class Field>
SphereSlopes<typename Field::Interval> certify_sphere_slopes_impl(const Field& field) {
    using I = typename Field::Interval;
    const I one = field.integer(1);
    SphereSlopes<I> result;
    result.c0 = enclose_density_slope(Family::C0, one);
    result.c1 = enclose_density_slope(Family::C1, one);
    result.o0 = enclose_density_slope(Family::O0, one);
    if (result.o0.slope) result.a_minus = *result.o0.slope;
    if (result.c0.slope && result.c1.slope) {
        if (certainly_less(*result.c1.slope, *result.c0.slope)) {
            result.a_plus = *result.c0.slope;
            result.a_plus_family = "C0";
        } else if (certainly_less(*result.c0.slope, *result.c1.slope)) {
            result.a_plus = *result.c1.slope;
            result.a_plus_family = "C1";
        }
    }
    // The paper's closed forms: -(pi/(12 sqrt 2)) [A + 4 psi(1/2) + 2 psi(3/2) - 6 psi(5/2)],
    // A = ln 64 + 8 for a_-, A = 24 + ln 8 for a_+.
    const I factor = -field.pi() / (field.integer(12) * sqrt(field.integer(2)));
    const I digammas = field.integer(4) * digamma(field.rational(Rational(1, 2))) +
                       field.integer(2) * digamma(field.rational(Rational(3, 2))) -
                       field.integer(6) * digamma(field.rational(Rational(5, 2)));
    result.closed_minus = factor * (log(field.integer(64)) + field.integer(8) + digammas);
    result.closed_plus = factor * (field.integer(24) + log(field.integer(8)) + digammas);
    if (result.a_minus) {
        result.minus_vs_closed = check_overlap(*result.a_minus, *result.closed_minus);
        result.minus_printed = check_printed(*result.a_minus, "-0.02941");
    }
    if (result.a_plus) {
        result.plus_vs_closed = check_overlap(*result.a_plus, *result.closed_plus);
        result.plus_printed = check_printed(*result.a_plus, "0.3555");
    }
    result.closed_plus_printed = check_printed(*result.closed_plus, "0.3555");
    return result;
}

template DensitySlope<DInterval> enclose_density_slope(Family, const DInterval&);
template DensitySlope<Ball> enclose_density_slope(Family, const Ball&);
template DensitySlope<DInterval> cubic_density_slope(Family, const DInterval&, const DInterval&);
template DensitySlope<Ball> cubic_density_slope(Family, const Ball&, const Ball&);
template std::optional<PieceRoot<DInterval>> certify_piece_root(Family, const DInterval&);
template std::optional<PieceRoot<Ball>> certify_piece_root(Family, const Ball&);
template std::optional<DInterval> smallest_root_within(const PieceRoot<DInterval>&, const DInterval&);
template std::optional<Ball> smallest_root_within(const PieceRoot<Ball>&, const Ball&);
template PrintedCheck<DInterval> check_printed(const DInterval&, const std::string&);
template PrintedCheck<Ball> check_printed(const Ball&, const std::string&);
template Outcome check_overlap(const DInterval&, const DInterval&);
template Outcome check_overlap(const Ball&, const Ball&);
OctahedralCrossover<DInterval> certify_octahedral_crossover(const DoubleField& field, long digits) {
    return certify_octahedral_crossover_impl(field, digits);
}
OctahedralCrossover<Ball> certify_octahedral_crossover(const BallField& field, long digits) {
    return certify_octahedral_crossover_impl(field, digits);
}
SphereSlopes<DInterval> certify_sphere_slopes(const DoubleField& field) { return certify_sphere_slopes_impl(field); }
SphereSlopes<Ball> certify_sphere_slopes(const BallField& field) { return certify_sphere_slopes_impl(field); }

}  // namespace superpack
