#include "superpack/cert/periodic_certificate.hpp"

#include <stdexcept>

namespace superpack {

namespace {

template <std::size_t n>
Json rationals_json(const std::array<Rational, n>& values) {
    Json result = Json::array();
    for (const Rational& x : values) result.push_back(rational_text(x));
    return result;
}

}  // namespace

Json periodic_packing_json(const PeriodicPacking& packing) {
    Json cell = Json::array(), particles = Json::array();
    for (const auto& row : packing.cell) cell.push_back(rationals_json(row));
    for (std::size_t i = 0; i < packing.centers.size(); ++i)
        particles.push_back(Json{{"center", rationals_json(packing.centers[i])}, {"quaternion", rationals_json(packing.quaternions[i])}});
    return Json{{"p", rational_text(packing.p)}, {"cell", cell}, {"particles", particles}};
}

template <class Field>
Json periodic_certificate(const PeriodicCertificate<typename Field::Interval>& proved, const Field& field, long digits,
                          const std::string& command) {
    if (proved.status != Outcome::proved) throw std::runtime_error("certificate: the periodic packing is not proved");
    Json data = periodic_packing_json(proved.packing);
    data["packing"] = true;
    Json pairs = Json::array();
    for (const PairSeparation& pair : proved.pairs)
        pairs.push_back(Json{{"first", pair.first},
                             {"second", pair.second},
                             {"shift", Json::array({pair.shift[0], pair.shift[1], pair.shift[2]})},
                             {"normal", rationals_json(pair.normal)}});
    const Json proof{{"kind", "separating-planes"}, {"radius", rational_text(proved.radius)}, {"pairs", pairs}};
    const Rational& p = proved.packing.p;
    const Json inputs{{"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}, {"particles", proved.packing.centers.size()}};
    return certificate_document(certificate_head(command, field, digits), Json{{"kind", "periodic-packing"}, {"data", data}}, inputs,
                                proof);
}

template Json periodic_certificate(const PeriodicCertificate<DInterval>&, const DoubleField&, long, const std::string&);
template Json periodic_certificate(const PeriodicCertificate<Ball>&, const BallField&, long, const std::string&);

}  // namespace superpack
