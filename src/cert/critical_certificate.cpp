#include "superpack/cert/critical_certificate.hpp"

#include <algorithm>
#include <stdexcept>

#include "superpack/cert/certificate_partition.hpp"
#include "superpack/problems/critical/critical_chart.hpp"

namespace superpack {

namespace {

using I = DInterval;

Json chart_box_json(const ChartBox<I>& box) {
    return Json{{"configuration", configuration_name(box.configuration)},
                {"face2", box.face2},
                {"face3", box.face3},
                {"x", box_json(std::vector<I>(box.x.begin(), box.x.end()))}};
}

std::vector<I> entries(const Basis<I>& basis) {
    std::vector<I> all;
    for (const auto& row : basis) all.insert(all.end(), row.begin(), row.end());
    return all;
}

Json image_json(const ChartImage& image) {
    Json inverse = Json::array();
    for (const Coefficients& row : image.inverse) inverse.push_back(coefficients_json(row));
    return Json{{"configuration", configuration_name(image.configuration)},
                {"inverse", inverse},
                {"perm", image.perm},
                {"sign", image.sign}};
}

// Region k with the images that point to it. Its KKT leaf is the reference optimum's, from which
// certify_closing_region built it (critical_setup).
Json region_json(const CriticalResult<I>& result, std::size_t k) {
    const ClosingRegion<I>& region = result.regions[k];
    const LocalOptimum<I>& optimum = *result.reference.optimum;
    Json pairs = Json::array(), images = Json::array();
    for (const Coefficients& c : region.contacts) pairs.push_back(coefficients_json(c));
    for (const ChartImage& image : result.images)
        if (image.region == k) images.push_back(image_json(image));
    std::vector<I> root = entries(*optimum.basis);
    root.insert(root.end(), optimum.multipliers.begin(), optimum.multipliers.end());
    const Json kkt{{"kind", "krawczyk"}, {"status", "unique"}, {"box", box_json(optimum.search_box)}, {"root", box_json(root)}};
    return Json{{"contact_pairs", pairs},
                {"kkt", kkt},
                {"rho", rational_text(Rational(static_cast<long>(region.rho)))},
                {"box", box_json(entries(region.region))},
                {"images", images}};
}

// The whole domain's start boxes, in order, are exactly top_level_domain().
bool whole_domain(const std::vector<ChartBox<I>>& boxes) {
    const std::vector<ChartBox<I>> top = top_level_domain();
    if (boxes.size() != top.size()) return false;
    for (std::size_t k = 0; k < top.size(); ++k) {
        if (boxes[k].configuration != top[k].configuration || boxes[k].face2 != top[k].face2 || boxes[k].face3 != top[k].face3)
            return false;
        for (int j = 0; j < chart_dimension; ++j)
            if (boxes[k].x[j].lower() != top[k].x[j].lower() || boxes[k].x[j].upper() != top[k].x[j].upper()) return false;
    }
    return true;
}

}  // namespace

Json critical_certificate(const CriticalResult<I>& result, const CriticalOptions& options) {
    if (result.status != Outcome::proved) throw std::runtime_error("certificate: the bound is not proved");
    if (result.trees.size() != result.boxes.size() || result.boxes.empty())
        throw std::runtime_error("certificate: the run did not record its trees");
    std::size_t bytes = 0;
    for (const std::string& tree : result.trees) bytes += tree.size();
    if (bytes > critical_certificate_bytes - (std::size_t{1} << 20))
        throw InputError("critical --certificate: the trees take " + std::to_string(bytes) +
                         " bytes, above the checker's file limit of " +
                         std::to_string(critical_certificate_bytes >> 20) + " MiB: certify fewer boxes (more shards, at a larger --split)");
    const DoubleField field;
    Json boxes = Json::array(), regions = Json::array();
    for (const ChartBox<I>& box : result.boxes) boxes.push_back(chart_box_json(box));
    // A region without images in the chart (a seven-pair optimum, NOTES.md 12.7) closes no box.
    for (std::size_t k = 0; k < result.regions.size(); ++k)
        if (std::any_of(result.images.begin(), result.images.end(), [k](const ChartImage& image) { return image.region == k; }))
            regions.push_back(region_json(result, k));
    const Json data{{"p", rational_text(options.p)},
                    {"threshold", exact_interval_json(result.threshold)},
                    {"volume", exact_interval_json(result.volume)},
                    {"upper_phi", exact_interval_json(result.volume / result.threshold)},
                    {"domain", whole_domain(result.boxes) ? "whole" : "boxes"}};
    const Json proof{{"kind", "critical-lattice"}, {"regions", regions}, {"boxes", boxes}, {"trees", result.trees}};
    const Json claim{{"kind", "critical-lattice"}, {"data", data}};
    const Json inputs{{"p", rational_text(options.p)}, {"p_decimal", decimal_or_fraction_text(options.p)},
                      {"gap", rational_text(options.gap)}};
    return certificate_document(certificate_head("critical", field, 15), claim, inputs, proof);
}

Json critical_cover_certificate(const CoverParts& parts, const std::string& directory, int threads) {
    const DoubleField field;
    const Json data{{"p", parts.p},
                    {"threshold", parts.threshold},
                    {"volume", parts.volume},
                    {"upper_phi", parts.upper_phi},
                    {"split", parts.split}};
    const Json claim{{"kind", "critical-lattice-cover"}, {"data", data}};
    const Json inputs{{"p", parts.p}, {"p_decimal", parts.p_decimal}, {"gap", parts.gap}};
    const Json proof{{"kind", "critical-lattice-cover"}, {"files", parts.names}};
    return certificate_document(certificate_head("critical", field, 15), claim, inputs, proof, directory, threads);
}

}  // namespace superpack
