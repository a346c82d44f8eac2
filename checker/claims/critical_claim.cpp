#include "checker/claims/critical_claim.hpp"

#include <sstream>
#include <tuple>

#include "checker/core/render.hpp"

namespace superpack_checker {

CriticalBound read_critical_bound(Context& context, const Json& data, const mpq_class& p) {
    context.current_step = "claim.data";
    const mpfr_prec_t precision = context.precision();
    const Real threshold = context.interval(context.member(data, "threshold", "claim.data"), "claim.data.threshold");
    if (!mpfr_equal_p(threshold.lo(), threshold.hi())) context.malformed("claim.data.threshold", "T must be a point (lo = hi)");
    context.require(positive(threshold), "claim.data.threshold", "T is not positive");
    const Real own_volume = superball_volume(rational(p, precision));
    const Real volume = proved_enclosure(context, context.member(data, "volume", "claim.data"), "claim.data.volume", own_volume);
    const Real volume_lo = lower_point(volume);
    context.require(!less(threshold, volume_lo), "claim.data.threshold",
                    "T is below V(K): the bound V(K) / T on the density would exceed 1");
    return CriticalBound{threshold, own_volume, volume, volume_lo};
}

Real read_upper_phi(Context& context, const Json& data, const CriticalBound& bound) {
    context.current_step = "claim.data";
    return proved_enclosure(context, context.member(data, "upper_phi", "claim.data"), "claim.data.upper_phi",
                            bound.own_volume / bound.threshold);
}

bool DomainBox::operator<(const DomainBox& other) const {
    return std::tie(configuration, face2, face3, ends) < std::tie(other.configuration, other.face2, other.face3, other.ends);
}
bool DomainBox::operator==(const DomainBox& other) const {
    return std::tie(configuration, face2, face3, ends) == std::tie(other.configuration, other.face2, other.face3, other.ends);
}

DomainBox domain_box(const ChartBox& box) {
    DomainBox key;
    key.configuration = box.configuration;
    key.face2 = box.face2;
    key.face3 = box.face3;
    for (int k = 0; k < chart_dimension; ++k) {
        key.ends[2 * k] = mpfr_get_d(box.x[k].lo(), MPFR_RNDN);  // exact: a binary64 end
        key.ends[2 * k + 1] = mpfr_get_d(box.x[k].hi(), MPFR_RNDN);
    }
    return key;
}

std::string domain_box_text(const DomainBox& box) {
    std::ostringstream text;
    text.precision(17);
    text << configuration_name(box.configuration) << ", faces " << box.face2 << " and " << box.face3 << ", x in";
    for (int k = 0; k < chart_dimension; ++k) text << (k ? " x " : " ") << "[" << box.ends[2 * k] << ", " << box.ends[2 * k + 1] << "]";
    return text.str();
}

std::array<DomainBox, 2> halves(const DomainBox& box) {
    int widest = 0;
    for (int k = 1; k < chart_dimension; ++k)
        if (box.ends[2 * k + 1] - box.ends[2 * k] > box.ends[2 * widest + 1] - box.ends[2 * widest]) widest = k;
    const double middle = box.ends[2 * widest] / 2 + box.ends[2 * widest + 1] / 2;
    std::array<DomainBox, 2> result{box, box};
    result[0].ends[2 * widest + 1] = middle;
    result[1].ends[2 * widest] = middle;
    return result;
}

std::vector<DomainBox> chart_domain(int split) {
    std::vector<DomainBox> boxes;
    for (const Configuration configuration : {Configuration::a3, Configuration::w})
        for (int face2 = 0; face2 < 6; ++face2)
            for (int face3 = face2; face3 < 6; ++face3)
                for (int piece = 0; piece < 4; ++piece) {
                    const double s = 0.5 * (piece / 2), t = 0.5 * (piece % 2);
                    boxes.push_back(DomainBox{configuration, face2, face3, {s, s + 0.5, t, t + 0.5, -1, 1, -1, 1, -1, 1, -1, 1}});
                }
    for (int level = 0; level < split; ++level) {
        std::vector<DomainBox> next;
        for (const DomainBox& box : boxes)
            for (const DomainBox& half : halves(box)) next.push_back(half);
        boxes.swap(next);
    }
    return boxes;
}

std::string whole_domain_words(int split, std::size_t start_boxes) {
    const bool uniform = start_boxes == (std::size_t{168} << split);
    const std::string times = std::to_string(split) + (split == 1 ? " time" : " times") + (uniform ? "" : " or more");
    const std::string pieces = split == 0 && uniform ? std::string()
                                                     : ", each bisected " + times +
                                                           " at the midpoint of its widest coordinate: " +
                                                           std::to_string(start_boxes) + " start boxes";
    return "on the whole chart domain of NOTES.md 12.2 (the 168 top-level boxes: Minkowski's configurations A3 and W, "
           "faces face2 <= face3, s and t in [0, 1], a2, c2, a3, c3 in [-1, 1]" +
           pieces + ")";
}

const char* const whole_domain_consequence =
    "so, since a critical lattice of 2K has a basis of one of these configurations (Minkowski; premises P1-P2 of "
    "NOTES.md 12.1), every lattice packing of K has density at most ";

}  // namespace superpack_checker
