#include "superpack/cert/star_lattice_certificate.hpp"

#include <mpfr.h>

#include <array>
#include <stdexcept>

#include "superpack/arith/exact.hpp"
#include "superpack/arith/mpfr_bounds.hpp"
#include "superpack/cert/lattice_certificate.hpp"
#include "superpack/geometry/star_cases.hpp"

namespace superpack {

namespace {

// x rounded to a multiple of 2^-bits (its lower end first taken to 128 bits, within a ball's
// radius or a binary64 interval's width of x).
template <class I>
Rational rounded_point(const I& x, int bits) {
    mpfr_t lo, hi;
    mpfr_inits2(128, lo, hi, static_cast<mpfr_ptr>(nullptr));
    get_bounds(lo, hi, x);
    Rational end;
    mpfr_get_q(end.get_mpq_t(), lo);
    mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
    mpz_class scale, steps;
    mpz_ui_pow_ui(scale.get_mpz_t(), 2, bits);
    const Rational scaled = end * scale;
    mpz_fdiv_q(steps.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());
    Rational result(steps, scale);
    result.canonicalize();  // GMP's arithmetic and comparisons assume lowest terms
    return result;
}

std::string coefficients_text(const Coefficients& c) {
    return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ")";
}

// The witness in the given basis: its coefficients, the rational point x and g(x), g(x - v).
template <class Field>
Json witness_json(const LatticeCheck<typename Field::Interval>& check, const Basis<Rational>& basis, const Superball& body,
                  const Field& field) {
    using I = typename Field::Interval;
    const Coefficients& c = check.witness->coefficients;
    std::array<Rational, 3> v;
    for (int j = 0; j < 3; ++j) v[j] = c[0] * basis[0][j] + c[1] * basis[1][j] + c[2] * basis[2][j];
    // The box cover's point lies well inside both bodies: the coarsest dyadic grid that keeps it
    // inside both gives the shortest point to read and to check.
    Json point = Json::array();
    std::vector<I> inside, translate;
    for (int bits = 8;; bits += 8) {
        point = Json::array();
        inside.clear();
        translate.clear();
        for (int j = 0; j < 3; ++j) {
            const Rational x = rounded_point(check.witness_point->point[j], bits);
            point.push_back(rational_text(x));
            inside.push_back(field.rational(x));
            translate.push_back(field.rational(x - v[j]));
        }
        if (in_interior(body, inside) == Outcome::proved && in_interior(body, translate) == Outcome::proved) break;
        if (bits == 128)
            throw std::runtime_error("certificate: the witness point is not certainly inside both bodies once made rational");
    }
    const I q = field.rational(2 * body.p);
    return Json{{"coefficients", coefficients_json(c)},
                {"point", point},
                {"values", Json::array({exact_interval_json(gauge_power(inside, q)), exact_interval_json(gauge_power(translate, q))})}};
}

}  // namespace

template <class Field>
Json star_lattice_certificate(const LatticeCheck<typename Field::Interval>& check, const Basis<Rational>& basis,
                              const Rational& p, const Field& field, long digits) {
    using I = typename Field::Interval;
    if (check.verdict == Outcome::undecided) throw std::runtime_error("certificate: the lattice check is undecided");
    if (!(p < Rational(1, 2))) throw std::logic_error("star_lattice_certificate: p >= 1/2 has the lattice-check kind");
    const Superball body = make_superball(3, p);
    const Json basis_json = rational_basis_json(basis);
    const bool packing = check.verdict == Outcome::proved;
    Json data{{"basis", basis_json}, {"p", rational_text(p)}, {"packing", packing}};
    Json proof;
    if (packing) {
        // Every candidate, in the reduced basis as enumerated, decided by the closed form: the
        // only overlap test the checker replays.
        proof = enumeration_proof_json(check, basis, field);
        Json candidates = Json::array();
        for (const auto& candidate : check.evaluated) {
            if (star_disjoint_by_cases(body, std::vector<I>(candidate.vector.begin(), candidate.vector.end())) != Outcome::proved)
                throw std::runtime_error("certificate: the candidate " + coefficients_text(candidate.coefficients) +
                                         " is disjoint by the box cover alone, which the checker does not replay");
            candidates.push_back(Json{{"coefficients", coefficients_json(representative(candidate.enumerated))}, {"status", "disjoint"}});
        }
        proof["candidates"] = candidates;
    } else {
        data["witness"] = witness_json(check, basis, body, field);
        proof = Json{{"kind", "witness-point"}};  // the point is its own proof
    }
    Json claim{{"kind", "star-lattice-check"}, {"data", data}};
    Json inputs{{"basis", basis_json}, {"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}};
    return certificate_document(certificate_head("check-lattice", field, digits), claim, inputs, proof);
}

template <class Field>
Json exact_lattice_certificate(const LatticeCheck<typename Field::Interval>& check, const Basis<Rational>& basis,
                               const Rational& p, const Field& field, long digits) {
    return p < Rational(1, 2) ? star_lattice_certificate(check, basis, p, field, digits)
                              : lattice_certificate(check, basis, p, field, digits);
}

template Json exact_lattice_certificate(const LatticeCheck<DInterval>&, const Basis<Rational>&, const Rational&, const DoubleField&, long);
template Json exact_lattice_certificate(const LatticeCheck<Ball>&, const Basis<Rational>&, const Rational&, const BallField&, long);
template Json star_lattice_certificate(const LatticeCheck<DInterval>&, const Basis<Rational>&, const Rational&, const DoubleField&, long);
template Json star_lattice_certificate(const LatticeCheck<Ball>&, const Basis<Rational>&, const Rational&, const BallField&, long);

}  // namespace superpack
