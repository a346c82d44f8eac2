#include "superpack/arith/mpfr_bounds.hpp"
#include "superpack/geometry/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace superpack {

const char* to_string(Verdict verdict) {
    switch (verdict) {
        case Verdict::admissible: return "admissible";
        case Verdict::overlapping: return "overlapping";
        case Verdict::undecided: return "undecided";
    }
    return "undecided";
}

namespace {

// The largest integer N with N <= every value of x (x certainly nonnegative), or -1 when x is
// unbounded or too large to enumerate.
template <class I>
long floor_of_upper(const I& x) {
    mpfr_t lo, hi;
    mpfr_init2(lo, 128);
    mpfr_init2(hi, 128);
    get_bounds(lo, hi, x);
    const double upper = mpfr_get_d(hi, MPFR_RNDU);
    mpfr_clear(lo);
    mpfr_clear(hi);
    if (!std::isfinite(upper) || upper > 1000.0) return -1;
    return static_cast<long>(std::floor(upper));
}

template <class I>
std::array<I, 3> cross(const std::array<I, 3>& u, const std::array<I, 3>& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

}  // namespace

template <class I>
LatticeCheck<I> check_lattice(const Basis<I>& basis, const I& p, const ContactProof& proved_contact) {
    const auto field = field_of(p);
    const I two = field.integer(2);
    LatticeCheck<I> check;
    // The criterion ||u - v||_(2p) >= 2 needs a convex body: p >= 1/2 on the whole piece.
    if (!certainly_nonnegative(field.integer(2) * p - field.integer(1)))
        throw InputError("the packing criterion needs p >= 1/2 on the whole p interval");
    const I det = determinant(basis);
    if (contains_zero(det)) {
        check.reason = "the basis is not certainly nonsingular (determinant encloses 0)";
        return check;
    }
    // Coefficient box: a_i = (e_j x e_k) . v / det, and |(e_j x e_k) . v| <= ||e_j x e_k||_1 ||v||_inf
    // <= ||e_j x e_k||_1 ||v||_(2p); so ||v||_(2p) <= 2 forces |a_i| <= 2 ||e_j x e_k||_1 / |det|.
    for (int i = 0; i < 3; ++i) {
        const auto normal = cross(basis[(i + 1) % 3], basis[(i + 2) % 3]);
        const I bound = two * (abs(normal[0]) + abs(normal[1]) + abs(normal[2])) / abs(det);
        const long n = floor_of_upper(bound);
        if (n < 0) {
            check.reason = "the coefficient box is too large to enumerate (basis too skewed or too wide)";
            return check;
        }
        check.coefficient_bound[i] = n;
    }
    const I two_p = field.integer(2) * p;
    const I inverse_two_p = field.integer(1) / two_p;
    const Coefficients& n = check.coefficient_bound;
    std::vector<LatticeVector<I>> below;
    // One of v, -v: the first nonzero coefficient positive.
    for (long a = 0; a <= n[0]; ++a)
        for (long b = (a == 0 ? 0 : -n[1]); b <= n[1]; ++b)
            for (long c = (a == 0 && b == 0 ? 1 : -n[2]); c <= n[2]; ++c) {
                auto coordinate = [&](int j) {
                    return field.integer(a) * basis[0][j] + field.integer(b) * basis[1][j] + field.integer(c) * basis[2][j];
                };
                const std::array<I, 3> v{coordinate(0), coordinate(1), coordinate(2)};
                bool outside = false;
                // ||v||_(2p) >= |v_j|: a coordinate certainly beyond 2 settles the candidate.
                for (int j = 0; j < 3; ++j)
                    if (certainly_less(two, abs(v[j]))) outside = true;
                if (outside) {
                    ++check.excluded_by_max_norm;
                    continue;
                }
                const std::vector<I> coordinates(v.begin(), v.end());
                const I norm = pow_nonneg(gauge_power(coordinates, two_p), inverse_two_p);
                LatticeVector<I> candidate{{a, b, c}, v, norm};
                check.evaluated.push_back(candidate);
                if (certainly_less(norm, two)) {
                    below.push_back(candidate);
                } else if (!certainly_less(two, norm)) {
                    if (proved_contact(candidate.coefficients)) {
                        check.contact_vectors.push_back({a, b, c});
                        check.contact_vectors.push_back({-a, -b, -c});
                    } else {
                        check.near_contacts.push_back(candidate);
                    }
                }
            }
    // min over all nonzero vectors: those outside the evaluated set have norm > 2.
    if (!check.evaluated.empty()) {
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
    std::ostringstream reason;
    if (!below.empty()) {
        check.witness = *std::min_element(below.begin(), below.end(), [](const auto& x, const auto& y) {
            return mid_double(x.norm) < mid_double(y.norm);
        });
        check.verdict = Verdict::overlapping;
        reason << below.size() << " lattice vector(s) (up to sign) with norm certainly < 2";
    } else if (!check.near_contacts.empty()) {
        reason << check.near_contacts.size()
               << " vector(s) (up to sign) with a norm enclosure containing 2 that no contact identity decides";
    } else {
        check.verdict = Verdict::admissible;
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

// x^k for a whole k >= 0, exactly.
Rational power(const Rational& x, long k) {
    Rational result = 1;
    for (long i = 0; i < k; ++i) result *= x;
    return result;
}

// Exactly decides ||v||_(2p) = 2, or returns false when the exact test does not apply.
bool exact_norm_is_two(const std::array<Rational, 3>& v, const Rational& p) {
    Rational two_p = 2 * p;
    two_p.canonicalize();
    const mpz_class& m = two_p.get_num();
    const mpz_class& n = two_p.get_den();
    if (!m.fits_slong_p() || m > 64) return false;
    if (n == 1) {  // sum |v_i|^m = 2^m in rationals
        Rational sum = 0;
        for (const Rational& x : v) sum += power(abs(x), m.get_si());
        return sum == power(Rational(2), m.get_si());
    }
    // Nonzero coordinates sharing one absolute value a, k of them: k a^(m/n) = 2^(m/n)
    // <=> (a/2)^m = k^(-n) (both sides positive).
    Rational a = 0;
    long k = 0;
    for (const Rational& x : v) {
        if (x == 0) continue;
        if (k > 0 && abs(x) != a) return false;
        a = abs(x);
        ++k;
    }
    if (k == 0 || !n.fits_slong_p() || n > 64) return false;
    return power(a / 2, m.get_si()) * power(Rational(k), n.get_si()) == 1;
}


template <class Field>
LatticeCheck<typename Field::Interval> check_exact(const Basis<Rational>& basis, const Rational& p, const Field& field) {
    if (p < Rational(1, 2)) throw InputError("check-lattice needs p >= 1/2 (the superball must be convex)");
    return check_lattice(enclose_basis(basis, field), field.rational(p), [&](const Coefficients& c) {
        std::array<Rational, 3> v;
        for (int j = 0; j < 3; ++j) v[j] = c[0] * basis[0][j] + c[1] * basis[1][j] + c[2] * basis[2][j];
        return exact_norm_is_two(v, p);
    });
}

}  // namespace

LatticeCheck<DInterval> check_exact_lattice(const Basis<Rational>& basis, const Rational& p, const DoubleField& field) {
    return check_exact(basis, p, field);
}

LatticeCheck<Ball> check_exact_lattice(const Basis<Rational>& basis, const Rational& p, const BallField& field) {
    return check_exact(basis, p, field);
}

Json coefficients_json(const Coefficients& c) { return Json::array({c[0], c[1], c[2]}); }

template <class I>
Json lattice_check_json(const LatticeCheck<I>& check, bool with_evaluated) {
    auto vector_json = [](const LatticeVector<I>& x) {
        Json coordinates = Json::array();
        for (const I& value : x.vector) coordinates.push_back(enclosure_json(value));
        return Json{{"coefficients", coefficients_json(x.coefficients)}, {"vector", coordinates},
                    {"norm", enclosure_json(x.norm)}};
    };
    Json result;
    result["admissible"] = check.verdict == Verdict::admissible    ? Json(true)
                           : check.verdict == Verdict::overlapping ? Json(false)
                                                                   : Json(nullptr);
    result["verdict"] = to_string(check.verdict);
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
    result["coefficient_bound"] = coefficients_json(check.coefficient_bound);
    result["excluded_by_max_norm"] = check.excluded_by_max_norm;
    if (with_evaluated) {
        Json evaluated = Json::array();
        for (const auto& x : check.evaluated) evaluated.push_back(vector_json(x));
        result["evaluated"] = evaluated;
    }
    return result;
}

template LatticeCheck<DInterval> check_lattice(const Basis<DInterval>&, const DInterval&, const ContactProof&);
template LatticeCheck<Ball> check_lattice(const Basis<Ball>&, const Ball&, const ContactProof&);
template Json lattice_check_json(const LatticeCheck<DInterval>&, bool);
template Json lattice_check_json(const LatticeCheck<Ball>&, bool);

}  // namespace superpack
