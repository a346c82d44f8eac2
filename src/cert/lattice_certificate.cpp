#include "superpack/cert/lattice_certificate.hpp"

#include <algorithm>
#include <stdexcept>

#include "superpack/arith/exact.hpp"

namespace superpack {

namespace {

std::array<Rational, 3> exact_vector(const Basis<Rational>& basis, const Coefficients& c) {
    std::array<Rational, 3> v;
    for (int j = 0; j < 3; ++j) v[j] = c[0] * basis[0][j] + c[1] * basis[1][j] + c[2] * basis[2][j];
    return v;
}

}  // namespace

Json rational_basis_json(const Basis<Rational>& basis) {
    Json rows = Json::array();
    for (int i = 0; i < 3; ++i) {
        Json row = Json::array();
        for (int j = 0; j < 3; ++j) row.push_back(rational_text(basis[i][j]));
        rows.push_back(row);
    }
    return rows;
}

template <class Field>
Json enumeration_proof_json(const LatticeCheck<typename Field::Interval>& check, const Basis<Rational>& basis,
                            const Field& field) {
    using I = typename Field::Interval;
    // The enumeration ran on the reduced basis R = U B (NOTES.md 5.6): its transform, and the data
    // its coefficient bound comes from, |det R| and ||r_j x r_k||_1 (NOTES.md 5.2).
    const BasisReduction reduction = check.reduction ? *check.reduction : BasisReduction{true, "", identity_transform(), basis};
    const Basis<I> enclosed = enclose_basis(reduction.reduced, field);
    Json cross_norms = Json::array();
    for (int i = 0; i < 3; ++i) {
        const auto& u = enclosed[(i + 1) % 3];
        const auto& w = enclosed[(i + 2) % 3];
        const I norm = abs(u[1] * w[2] - u[2] * w[1]) + abs(u[2] * w[0] - u[0] * w[2]) + abs(u[0] * w[1] - u[1] * w[0]);
        cross_norms.push_back(exact_interval_json(norm));
    }
    return Json{{"kind", "enumeration"},
                {"reduction", reduction_json(reduction)},
                {"coefficient_bound", coefficients_json(check.coefficient_bound)},
                {"bound_data", Json{{"determinant", exact_interval_json(abs(determinant(enclosed)))}, {"cross_norms", cross_norms}}}};
}

template <class Field>
Json lattice_certificate(const LatticeCheck<typename Field::Interval>& check, const Basis<Rational>& basis,
                         const Rational& p, const Field& field, long digits) {
    using I = typename Field::Interval;
    if (check.verdict == Outcome::undecided) throw std::runtime_error("certificate: the lattice check is undecided");
    const Json basis_json = rational_basis_json(basis);
    const bool packing = check.verdict == Outcome::proved;

    const Basis<Rational>& reduced = check.reduction ? check.reduction->reduced : basis;
    Json candidates = Json::array(), contacts = Json::array();
    for (const auto& candidate : check.evaluated) {
        const bool contact = std::find(check.contact_vectors.begin(), check.contact_vectors.end(), candidate.coefficients) !=
                             check.contact_vectors.end();
        const I two = field.integer(2);
        // "undecided": a near contact, possible only beside a witness (an overlapping verdict).
        const char* status = contact                               ? "contact"
                             : certainly_less(candidate.norm, two) ? "below"
                             : certainly_less(two, candidate.norm) ? "above"
                                                                   : "undecided";
        // In the reduced basis, one triple per +-pair as the enumeration lists them.
        const Coefficients enumerated = representative(candidate.enumerated);
        candidates.push_back(Json{{"coefficients", coefficients_json(enumerated)},
                                  {"norm", exact_interval_json(candidate.norm)},
                                  {"status", status}});
        if (!contact) continue;
        // Each contact pair once, in the reduced basis, with its exact vector.
        const std::array<Rational, 3> vector = exact_vector(reduced, enumerated);
        Json exact = Json::array();
        for (const Rational& x : vector) exact.push_back(rational_text(x));
        contacts.push_back(Json{{"coefficients", coefficients_json(enumerated)},
                                {"vector", exact}});
    }
    Json contact_vectors = Json::array();
    for (const auto& c : check.contact_vectors) contact_vectors.push_back(coefficients_json(c));

    Json data{{"basis", basis_json}, {"p", rational_text(p)}, {"packing", packing}};
    Json proof = enumeration_proof_json(check, basis, field);
    proof["candidates"] = candidates;
    if (packing) {
        data["contacts"] = check.contacts();
        data["contact_vectors"] = contact_vectors;
        proof["contacts"] = contacts;  // each decided exactly, with its exact vector
    } else {
        const Coefficients& w = check.witness->coefficients;
        data["witness"] = Json{{"coefficients", coefficients_json(w)}, {"norm", exact_interval_json(check.witness->norm)}};
    }
    Json claim{{"kind", "lattice-check"}, {"data", data}};
    Json inputs{{"basis", basis_json}, {"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}};
    return certificate_document(certificate_head("check-lattice", field, digits), claim, inputs, proof);
}

template Json enumeration_proof_json(const LatticeCheck<DInterval>&, const Basis<Rational>&, const DoubleField&);
template Json enumeration_proof_json(const LatticeCheck<Ball>&, const Basis<Rational>&, const BallField&);
template Json lattice_certificate(const LatticeCheck<DInterval>&, const Basis<Rational>&, const Rational&, const DoubleField&, long);
template Json lattice_certificate(const LatticeCheck<Ball>&, const Basis<Rational>&, const Rational&, const BallField&, long);

}  // namespace superpack
