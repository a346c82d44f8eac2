#include "superpack/arith/mpfr_bounds.hpp"
#include "superpack/geometry/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "superpack/geometry/exact_norm.hpp"

namespace superpack {

const char* packing_word(Outcome verdict) {
    switch (verdict) {
        case Outcome::proved: return "admissible";
        case Outcome::refuted: return "overlapping";
        case Outcome::undecided: return "undecided";
    }
    return "undecided";
}

namespace {

// The largest integer N with N <= every value of x (x certainly nonnegative), or -1 when x is
// unbounded or larger than the box limit.
template <class I>
long floor_of_upper(const I& x) {
    mpfr_t lo, hi;
    mpfr_init2(lo, 128);
    mpfr_init2(hi, 128);
    get_bounds(lo, hi, x);
    const double upper = mpfr_get_d(hi, MPFR_RNDU);
    mpfr_clear(lo);
    mpfr_clear(hi);
    if (!std::isfinite(upper) || upper > static_cast<double>(enumeration_box_limit)) return -1;
    return static_cast<long>(std::floor(upper));
}

template <class I>
std::array<I, 3> cross(const std::array<I, 3>& u, const std::array<I, 3>& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// The box |a_i| <= n_i of coefficients holding every lattice vector with max norm at most 2,
// into check.coefficient_bound; false (with check.reason) when it is unbounded or holds more
// than enumeration_box_limit triples (a step of its own: for_each_candidate's bounds, apart from
// its enumeration).
template <class I>
bool bound_coefficients(const Basis<I>& basis, const I& det, LatticeCheck<I>& check) {
    const auto field = field_of(basis[0][0]);
    const I two = field.integer(2);
    // Coefficient box: a_i = (e_j x e_k) . v / det, and |(e_j x e_k) . v| <= ||e_j x e_k||_1 ||v||_inf,
    // so ||v||_inf <= 2 forces |a_i| <= 2 ||e_j x e_k||_1 / |det|.
    for (int i = 0; i < 3; ++i) {
        const auto normal = cross(basis[(i + 1) % 3], basis[(i + 2) % 3]);
        const I bound = two * (abs(normal[0]) + abs(normal[1]) + abs(normal[2])) / abs(det);
        const long n = floor_of_upper(bound);
        if (n < 0) {
            check.reason = "the coefficient box is too large to enumerate: |a_" + std::to_string(i + 1) +
                           "| may reach beyond " + std::to_string(enumeration_box_limit) + " (basis too flat or too wide)";
            return false;
        }
        check.coefficient_bound[i] = n;
    }
    long triples = 1;  // at most the limit times 2 * limit + 1 at each step: no overflow
    for (long n : check.coefficient_bound) {
        triples *= 2 * n + 1;
        if (triples > enumeration_box_limit) {
            check.reason = "the coefficient box |a| <= " + std::to_string(check.coefficient_bound[0]) + ", |b| <= " +
                           std::to_string(check.coefficient_bound[1]) + ", |c| <= " +
                           std::to_string(check.coefficient_bound[2]) + " holds more than " +
                           std::to_string(enumeration_box_limit) + " triples, the enumeration's limit";
            return false;
        }
    }
    return true;
}

// check.min_norm, the min over all nonzero vectors: those outside the evaluated set have norm
// > 2, so it is the min over the evaluated ones, capped at 2 (a step of its own: check_lattice's
// summary, apart from its enumeration).
template <class I>
void enclose_min_norm(LatticeCheck<I>& check, const I& two) {
    mpfr_t lo, hi, best_lo, best_hi;
    for (auto* x : {&lo, &hi, &best_lo, &best_hi}) mpfr_init2(*x, 256);
    mpfr_set_ui(best_lo, 2, MPFR_RNDD);
    mpfr_set_inf(best_hi, 1);
    for (const auto& candidate : check.evaluated) {
        get_bounds(lo, hi, candidate.norm);
        mpfr_min(best_lo, best_lo, lo, MPFR_RNDD);
        mpfr_min(best_hi, best_hi, hi, MPFR_RNDU);
    }
    if (mpfr_inf_p(best_hi) == 0) {
        const double low = mpfr_get_d(best_lo, MPFR_RNDD), high = mpfr_get_d(best_hi, MPFR_RNDU);
        check.min_norm = from_doubles(two, std::min(low, high), high);
    }
    for (auto* x : {&lo, &hi, &best_lo, &best_hi}) mpfr_clear(*x);
}

}  // namespace

template <class I>
bool for_each_candidate(const Basis<I>& basis, LatticeCheck<I>& check, const CandidateVisitor<I>& visit) {
    const auto field = field_of(basis[0][0]);
    const I two = field.integer(2);
    const I det = determinant(basis);
    if (contains_zero(det)) {
        check.reason = "the basis is not certainly nonsingular (determinant encloses 0)";
        return false;
    }
    if (!bound_coefficients(basis, det, check)) return false;
    const Coefficients& n = check.coefficient_bound;
    std::size_t visited = 0;
    // One of v, -v: the first nonzero coefficient positive.
    for (long a = 0; a <= n[0]; ++a)
        for (long b = (a == 0 ? 0 : -n[1]); b <= n[1]; ++b)
            for (long c = (a == 0 && b == 0 ? 1 : -n[2]); c <= n[2]; ++c) {
                auto coordinate = [&](int j) {
                    return field.integer(a) * basis[0][j] + field.integer(b) * basis[1][j] + field.integer(c) * basis[2][j];
                };
                const std::array<I, 3> v{coordinate(0), coordinate(1), coordinate(2)};
                bool outside = false;
                for (int j = 0; j < 3; ++j)
                    if (certainly_less(two, abs(v[j]))) outside = true;
                if (outside) {
                    ++check.excluded_by_max_norm;
                    continue;
                }
                if (visited == enumeration_candidate_limit) {
                    check.reason = "more than " + std::to_string(enumeration_candidate_limit) +
                                   " lattice vectors with every coordinate at most 2 in size, the enumeration's limit "
                                   "(the lattice is too dense: |det| is about 64 / that count)";
                    check.evaluated.clear();
                    check.contact_vectors.clear();
                    check.near_contacts.clear();
                    return false;
                }
                ++visited;
                visit({a, b, c}, v);
            }
    return true;
}

template <class I>
LatticeCheck<I> check_lattice(const Basis<I>& basis, const I& p, const ContactProof& proved_contact) {
    const auto field = field_of(p);
    const I two = field.integer(2);
    LatticeCheck<I> check;
    // The criterion ||u - v||_(2p) >= 2 needs a convex body: p >= 1/2 on the whole piece.
    if (!certainly_nonnegative(field.integer(2) * p - field.integer(1)))
        throw InputError("the packing criterion needs p >= 1/2 on the whole p interval");
    if (!certainly_nonnegative(field.integer(1000000000000000) - p))
        throw InputError("the lattice check supports p <= 10^15 (beyond, a norm 2 (1 + 2^-2p)^(1/(2p)) is within "
                         "binary64's rounding of 2, and the 2p-th powers of coordinates near 2 overflow)");
    const I two_p = field.integer(2) * p;
    const I inverse_two_p = field.integer(1) / two_p;
    std::vector<LatticeVector<I>> below;
    // ||v||_(2p) >= ||v||_inf, so the candidates (every coordinate at most 2 in size) hold every
    // vector of norm <= 2.
    const bool complete = for_each_candidate<I>(basis, check, [&](const Coefficients& abc, const std::array<I, 3>& v) {
        // ||v|| = 2 ||v/2||: the halves are at most 1 in size here, so their 2p-th powers
        // cannot overflow (2^(2p) does beyond p = 512 in binary64). Halving is exact.
        const std::vector<I> halves{v[0] / two, v[1] / two, v[2] / two};
        const I norm = two * pow_nonneg(gauge_power(halves, two_p), inverse_two_p);
        LatticeVector<I> candidate{abc, abc, v, norm};
        check.evaluated.push_back(candidate);
        if (certainly_less(norm, two)) {
            below.push_back(candidate);
        } else if (!certainly_less(two, norm)) {
            if (proved_contact(candidate.coefficients)) {
                check.contact_vectors.push_back(abc);
                check.contact_vectors.push_back({-abc[0], -abc[1], -abc[2]});
            } else {
                check.near_contacts.push_back(candidate);
            }
        }
    });
    if (!complete) return check;
    if (!check.evaluated.empty()) enclose_min_norm(check, two);
    std::ostringstream reason;
    if (!below.empty()) {
        check.witness = *std::min_element(below.begin(), below.end(), [](const auto& x, const auto& y) {
            return mid_double(x.norm) < mid_double(y.norm);
        });
        check.verdict = Outcome::refuted;
        reason << below.size() << " lattice vector(s) (up to sign) with norm certainly < 2";
    } else if (!check.near_contacts.empty()) {
        reason << check.near_contacts.size()
               << " vector(s) (up to sign) with a norm enclosure containing 2 that no contact identity decides";
    } else {
        check.verdict = Outcome::proved;
        reason << "every candidate in the coefficient box has norm certainly > 2 or proved = 2 ("
               << check.contacts() << " contacts)";
    }
    check.reason = reason.str();
    return check;
}

Basis<Rational> parse_basis(const std::string& text) {
    Basis<Rational> basis;
    std::vector<std::string> rows;
    std::stringstream all(text);
    std::string row;
    while (std::getline(all, row, ';')) rows.push_back(row);
    if (rows.size() != 3) throw InputError("basis '" + text + "': expected 3 rows separated by ';'");
    for (int i = 0; i < 3; ++i) {
        std::vector<std::string> entries;
        std::stringstream line(rows[i]);
        std::string entry;
        while (std::getline(line, entry, ',')) entries.push_back(entry);
        if (entries.size() != 3) throw InputError("basis row " + std::to_string(i + 1) + " '" + rows[i] + "': expected 3 entries");
        for (int j = 0; j < 3; ++j) {
            const auto first = entries[j].find_first_not_of(" \t"), last = entries[j].find_last_not_of(" \t");
            if (first == std::string::npos) throw InputError("basis row " + std::to_string(i + 1) + ": empty entry");
            basis[i][j] = parse_rational(entries[j].substr(first, last - first + 1));
        }
    }
    if (determinant(basis) == 0) throw InputError("basis is singular (determinant 0)");
    return basis;
}

namespace {

// The check runs on the LLL-reduced basis R = U B, whose coefficient box is small for any basis
// of a lattice that is not itself very flat; a vector with coefficients c in R has coefficients
// c U in B, which is how every result is reported (NOTES.md 5.6).
template <class Field>
LatticeCheck<typename Field::Interval> check_exact(const Basis<Rational>& basis, const Rational& p, const Field& field) {
    using I = typename Field::Interval;
    if (p <= 0) throw InputError("check-lattice needs p > 0");
    const BasisReduction reduction = reduce_basis(basis);
    if (!reduction.done) {
        LatticeCheck<I> check;
        check.reason = reduction.reason;
        return check;
    }
    const Basis<Rational>& reduced = reduction.reduced;
    // Below p = 1/2 the body is a star body and each candidate goes to its overlap test.
    LatticeCheck<I> check =
        p < Rational(1, 2) ? check_star_lattice(enclose_basis(reduced, field), make_superball(3, p))
                           : check_lattice(enclose_basis(reduced, field), field.rational(p), [&](const Coefficients& c) {
                                 std::array<Rational, 3> v;
                                 for (int j = 0; j < 3; ++j) v[j] = c[0] * reduced[0][j] + c[1] * reduced[1][j] + c[2] * reduced[2][j];
                                 return decide_norm_is_two(v, p).answer == ExactNorm::two;
                             });
    // One per +-pair in the given basis too: v or -v, whichever has its first coefficient positive.
    auto to_given = [&](LatticeVector<I>& x) {
        x.coefficients = given_coefficients(x.enumerated, reduction.transform);
        if (representative(x.coefficients) == x.coefficients) return;
        for (int j = 0; j < 3; ++j) {
            x.coefficients[j] = -x.coefficients[j];
            x.enumerated[j] = -x.enumerated[j];
            x.vector[j] = -x.vector[j];
        }
    };
    for (auto& x : check.evaluated) to_given(x);
    for (auto& x : check.near_contacts) to_given(x);
    if (check.witness) {
        const LatticeVector<I> before = *check.witness;
        to_given(*check.witness);
        // K + v meets K at x exactly when K - v meets K at x - v: the point follows the sign.
        if (check.witness_point && check.witness->enumerated != before.enumerated) {
            StarOverlapWitness<I>& w = *check.witness_point;
            for (int j = 0; j < 3; ++j) w.point[j] = w.point[j] - before.vector[j];
            std::swap(w.value, w.value_at_translate);
        }
    }
    for (auto& c : check.contact_vectors) c = given_coefficients(c, reduction.transform);
    check.reduction = reduction;
    return check;
}

}  // namespace

LatticeCheck<DInterval> check_exact_lattice(const Basis<Rational>& basis, const Rational& p, const DoubleField& field) {
    return check_exact(basis, p, field);
}

LatticeCheck<Ball> check_exact_lattice(const Basis<Rational>& basis, const Rational& p, const BallField& field) {
    return check_exact(basis, p, field);
}

Json coefficients_json(const Coefficients& c) { return Json::array({c[0], c[1], c[2]}); }

Coefficients representative(const Coefficients& c) {
    const bool negative = c[0] < 0 || (c[0] == 0 && (c[1] < 0 || (c[1] == 0 && c[2] < 0)));
    return negative ? Coefficients{-c[0], -c[1], -c[2]} : c;
}

Json reduction_json(const BasisReduction& reduction) {
    Json transform = Json::array(), reduced = Json::array();
    for (int i = 0; i < 3; ++i) {
        transform.push_back(coefficients_json(reduction.transform[i]));
        Json row = Json::array();
        for (const Rational& x : reduction.reduced[i]) row.push_back(rational_text(x));
        reduced.push_back(row);
    }
    return Json{{"transform", transform},
                {"reduced_basis", reduced}};
}

template <class I>
Json lattice_check_json(const LatticeCheck<I>& check, bool with_evaluated) {
    auto vector_json = [](const LatticeVector<I>& x) {
        Json coordinates = Json::array();
        for (const I& value : x.vector) coordinates.push_back(enclosure_json(value));
        return Json{{"coefficients", coefficients_json(x.coefficients)}, {"vector", coordinates},
                    {"norm", enclosure_json(x.norm)}};
    };
    Json result;
    result["admissible"] = check.verdict == Outcome::proved    ? Json(true)
                           : check.verdict == Outcome::refuted ? Json(false)
                                                                   : Json(nullptr);
    result["verdict"] = packing_word(check.verdict);
    result["reason"] = check.reason;
    result["min_norm"] = check.min_norm ? enclosure_json(*check.min_norm) : Json(nullptr);
    result["contacts"] = check.contacts();
    Json contacts = Json::array();
    for (const auto& c : check.contact_vectors) contacts.push_back(coefficients_json(c));
    result["contact_vectors"] = contacts;
    Json near = Json::array();
    for (const auto& x : check.near_contacts) near.push_back(vector_json(x));
    result["near_contacts"] = near;
    result["witness"] = check.witness ? vector_json(*check.witness) : Json(nullptr);
    if (check.witness_point) {
        Json point = Json::array();
        for (const I& value : check.witness_point->point) point.push_back(enclosure_json(value));
        result["witness_point"] = Json{{"point", point},
                                       {"gauge_power", enclosure_json(check.witness_point->value)},
                                       {"gauge_power_at_translate", enclosure_json(check.witness_point->value_at_translate)}};
    }
    result["coefficient_bound"] = coefficients_json(check.coefficient_bound);
    result["excluded_by_max_norm"] = check.excluded_by_max_norm;
    // Coefficients above are in the given basis; the box is that of the reduced basis.
    result["reduction"] = check.reduction ? reduction_json(*check.reduction) : Json(nullptr);
    if (with_evaluated) {
        Json evaluated = Json::array();
        for (const auto& x : check.evaluated) evaluated.push_back(vector_json(x));
        result["evaluated"] = evaluated;
    }
    return result;
}

template bool for_each_candidate(const Basis<DInterval>&, LatticeCheck<DInterval>&, const CandidateVisitor<DInterval>&);
template bool for_each_candidate(const Basis<Ball>&, LatticeCheck<Ball>&, const CandidateVisitor<Ball>&);
template LatticeCheck<DInterval> check_lattice(const Basis<DInterval>&, const DInterval&, const ContactProof&);
template LatticeCheck<Ball> check_lattice(const Basis<Ball>&, const Ball&, const ContactProof&);
template Json lattice_check_json(const LatticeCheck<DInterval>&, bool);
template Json lattice_check_json(const LatticeCheck<Ball>&, bool);

}  // namespace superpack
