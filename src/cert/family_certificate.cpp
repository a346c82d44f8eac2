#include "superpack/cert/family_certificate.hpp"

#include <stdexcept>

#include "superpack/cert/certificate_partition.hpp"
#include "superpack/arith/decimal.hpp"

namespace superpack {

namespace {

// C0, C1: the Newton box of s (with the first Newton step recomputed for the record) and
// the root-free partition of [0, lower end of that box].
template <class I>
Json cubic_proof(const FamilyLattice<I>& lattice, const I& p) {
    const Family family = lattice.family;
    const RootLeaf<I>& newton = lattice.search.back();
    const I& box = newton.piece[0];
    auto equation = [&](const auto& s) { return cubic_equation(family, s, p); };
    const I derivative = equation(variable(box)).derivative;
    const I center = midpoint(box);
    const I image = center - equation(center) / derivative;
    Json newton_leaf{{"kind", "newton"},
                     {"box", box_json(std::vector<I>{box})},
                     {"midpoint", box_json(std::vector<I>{center})},
                     {"derivative", box_json(std::vector<I>{derivative})},
                     {"image", box_json(std::vector<I>{image})},
                     {"root", box_json(newton.root)},
                     {"reason", "N(X) = m - f(m)/f'(X) lies in the interior of X and f' != 0 on X"}};
    const std::vector<RootLeaf<I>> below(lattice.search.begin(), lattice.search.end() - 1);
    const std::vector<I> search_box{hull(field_of(p).integer(0), lower_point(box))};
    auto vector_equation = [&](const std::vector<I>& x) { return std::vector<I>{equation(x[0])}; };
    Json cases = Json::array();
    cases.push_back(newton_leaf);
    cases.push_back(partition_json(vector_equation, search_box, below));
    return Json{{"kind", "all"},
                {"text", "s is the unique root of the equation in the Newton box, and [0, lower end of that box] "
                         "holds no root, so s is the smallest positive root"},
                {"cases", cases}};
}

template <class I>
Json o1_proof(const FamilyLattice<I>& lattice, const I& p) {
    const auto field = field_of(p);
    auto equations = [&](const std::vector<I>& x) { return o1_equations(x, p); };
    const std::vector<I> box{hull(field.integer(0), field.integer(1)), hull(field.integer(-1), field.integer(1))};
    Json cases = Json::array();
    cases.push_back(partition_json(equations, box, lattice.search));
    return Json{{"kind", "all"},
                {"text", "the pieces partition [0,1] x [-1,1] (which holds every root of Eq. (12) with q >= 0); "
                         "each holds no root or exactly one, in its root box"},
                {"cases", cases}};
}

const char* family_formula(Family family) {
    switch (family) {
        case Family::C0: return "(s + t)^(2p) + s^(2p) + 2^(-2p) - 1 = 0 with t = 2^(-1/(2p)) (Eq. 2), s its smallest positive root";
        case Family::C1: return "(s + t)^(2p) + 2 s^(2p) - 1 = 0 with t = 2^(-1/(2p)) (Eq. 9), s its smallest positive root";
        case Family::O0: return "c = (1 - 2^(1-2p))^(1/(2p)) (Eq. 5)";
        case Family::O1: return "2|q|^(2p) + |s|^(2p) = 1, |l+q|^(2p) + |s-l|^(2p) + |l-q|^(2p) = 1 with l = 3^(-1/(2p)) "
                                "(Eq. 12); (q, s) its root with q >= 0 and the larger s (the Minkowski branch)";
    }
    return "";
}

}  // namespace

template <class I>
Json family_parameter_proof(const FamilyLattice<I>& lattice, const I& p) {
    if (lattice.status != FamilyStatus::certified)
        throw std::runtime_error(std::string("certificate: ") + to_string(lattice.family) + " is not certified at this p");
    switch (lattice.family) {
        case Family::C0:
        case Family::C1: return cubic_proof(lattice, p);
        case Family::O0:
            return Json{{"kind", "evaluation"},
                        {"reason", "no equation to solve: c, the basis of Eq. (5), V_sb and phi are direct evaluations at p"}};
        case Family::O1: return o1_proof(lattice, p);
    }
    throw std::logic_error("unknown family");
}

template <class Field>
Json family_certificate(const FamilyLattice<typename Field::Interval>& lattice, const Rational& p, const Field& field,
                        long digits) {
    using I = typename Field::Interval;
    if (lattice.status != FamilyStatus::certified)
        throw std::runtime_error(std::string("certificate: ") + to_string(lattice.family) + " is not certified at this p");
    const I p_interval = field.rational(p);
    Json parameters = Json::object();
    for (const auto& parameter : lattice.parameters) parameters[parameter.name] = exact_interval_json(parameter.value);
    const std::string family = to_string(lattice.family);
    const DecimalEnclosure phi_text = to_decimal(*lattice.phi, 17);
    Json claim{{"kind", "family-lattice"},
               {"text", "The " + family + " lattice of Jiao, Stillinger and Torquato (2009) at p = " + rational_text(p) +
                            ", built from " + family_formula(lattice.family) + ", has packing density phi = V_sb(p) / |det B| in [" +
                            phi_text.lo + ", " + phi_text.hi + "] (exact endpoints in data.phi)"},
               {"data", Json{{"family", family},
                             {"p", rational_text(p)},
                             {"parameters", parameters},
                             {"volume", exact_interval_json(*lattice.volume)},
                             {"determinant", exact_interval_json(*lattice.determinant)},
                             {"phi", exact_interval_json(*lattice.phi)}}}};
    Json inputs{{"family", family}, {"p", rational_text(p)}, {"p_decimal", decimal_or_fraction_text(p)}};
    const Json proof = family_parameter_proof(lattice, p_interval);
    return certificate_document(certificate_head("density", field, digits), claim, inputs, proof);
}

template Json family_parameter_proof(const FamilyLattice<DInterval>&, const DInterval&);
template Json family_parameter_proof(const FamilyLattice<Ball>&, const Ball&);
template Json family_certificate(const FamilyLattice<DInterval>&, const Rational&, const DoubleField&, long);
template Json family_certificate(const FamilyLattice<Ball>&, const Rational&, const BallField&, long);

}  // namespace superpack
