#include "superpack/cert/local_optimum_certificate.hpp"

#include <stdexcept>

#include "superpack/cert/certificate_partition.hpp"
#include "superpack/cert/family_certificate.hpp"
#include "superpack/geometry/superball.hpp"

namespace superpack {

template <class Field>
Json local_optimum_certificate(const LocalOptimum<typename Field::Interval>& local, const Rational& p, const Field& field,
                               long digits) {
    using I = typename Field::Interval;
    if (local.verdict != Outcome::proved) throw std::runtime_error("certificate: local optimality is not certified");
    const Basis<I>& basis = *local.basis;
    Json rows = Json::array(), pairs = Json::array();
    std::vector<I> root;
    for (const auto& row : basis) {
        rows.push_back(box_json(std::vector<I>(row.begin(), row.end())));
        root.insert(root.end(), row.begin(), row.end());
    }
    root.insert(root.end(), local.multipliers.begin(), local.multipliers.end());
    for (const Coefficients& c : local.contacts) pairs.push_back(coefficients_json(c));
    const I p_interval = field.rational(p);
    const I volume = enclose_ball_volume(p_interval, 3);
    const I det = determinant(basis);

    // The lattice check's verdict and enumeration, as a family certificate states them for its
    // interval basis (the contacts are those of the KKT equations).
    Json data = lattice_verdict_json(*local.check);
    data.update(Json{{"p", rational_text(p)},
                     {"contact_pairs", pairs},
                     {"basis", rows},
                     {"multipliers", box_json(local.multipliers)},
                     {"volume", exact_interval_json(volume)},
                     {"determinant", exact_interval_json(det)},
                     {"phi", exact_interval_json(*local.phi)}});
    const Json kkt{{"kind", "krawczyk"}, {"status", "unique"}, {"box", box_json(local.search_box)}, {"root", box_json(root)}};
    const Json proof{{"kind", "local-optimum"},
                     {"kkt", kkt},
                     {"second_order", Json{{"rho", rational_text(Rational(static_cast<long>(local.rho)))}}},
                     {"lattice", lattice_enumeration_json(*local.check)}};
    Json claim{{"kind", "local-optimum"}, {"data", data}};
    Json inputs{{"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}};
    return certificate_document(certificate_head("best", field, digits), claim, inputs, proof);
}

template Json local_optimum_certificate(const LocalOptimum<DInterval>&, const Rational&, const DoubleField&, long);
template Json local_optimum_certificate(const LocalOptimum<Ball>&, const Rational&, const BallField&, long);

}  // namespace superpack
