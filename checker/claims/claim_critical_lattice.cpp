// Claim kind "critical-lattice" (written by `superpack critical --certificate`; NOTES.md 12 and
// 12.8): at an exact p > 1/2, every lattice packing of the superball K whose chart basis lies in
// one of the stated chart boxes and satisfies the box's Minkowski configuration has |det| >= T,
// so its density is at most V(K) / T. With domain "whole" the boxes are the whole chart domain
// (the 168 top-level boxes of NOTES 12.2), which by Minkowski's theorem on critical lattices
// (premises P1-P2 of 12.1) bounds the density of every lattice packing of K.
//
// The replay, in the checker's arithmetic and its own copy of the producer's formulas:
//   1. V(K) (superball_volume) inside claim.data.volume; T a point with V_lo <= T (V_lo the
//      stated volume's lower end, a lower bound of V(K)).
//   2. The closing regions and their images (critical_region.hpp).
//   3. Every start box's tree (critical_tree.hpp): each cut and each leaf proved on its box.
//   4. upper_phi holds V(K) / T.
//
// Keys read: claim.data {p, threshold, volume, upper_phi, domain}; inputs {p, p_decimal, gap};
// proof {kind, regions [{contact_pairs, kkt {kind, status, box, root}, rho, box, images
// [{configuration, inverse, perm, sign}]}], boxes [{configuration, face2, face3, x}], trees}.
#include "checker/claims/claim_parts.hpp"
#include "checker/claims/critical_claim.hpp"
#include "checker/claims/critical_tree.hpp"
#include "checker/claims/literature.hpp"
#include "checker/core/limits.hpp"
#include "checker/core/render.hpp"

namespace superpack_checker {

namespace {

// The 168 top-level boxes of NOTES.md 12.2, in order.
bool whole_domain(const std::vector<ChartBox>& boxes) {
    const std::vector<DomainBox> domain = chart_domain(0);
    if (boxes.size() != domain.size()) return false;
    for (std::size_t k = 0; k < boxes.size(); ++k)
        if (!(domain_box(boxes[k]) == domain[k])) return false;
    return true;
}

std::string count_words(long n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

// The start boxes of proof.boxes (non-empty, at most max_chart_boxes), read, with one tree
// string per box in proof.trees.
struct StartBoxes {
    std::vector<ChartBox> boxes;
    const Json& trees;
};

// Reads the start boxes, and checks that each has its tree, before any tree is replayed.
StartBoxes read_start_boxes(Context& context, const Json& proof) {
    const Json& box_list = context.member(proof, "boxes", "proof");
    const Json& tree_list = context.member(proof, "trees", "proof");
    if (!box_list.is_array() || box_list.empty()) context.malformed("proof.boxes", "expected a non-empty array of chart boxes");
    if (box_list.size() > max_chart_boxes)
        context.malformed("proof.boxes", std::to_string(box_list.size()) + " chart boxes exceed the limit of " +
                                             std::to_string(max_chart_boxes) + " (max_chart_boxes)");
    if (!tree_list.is_array() || tree_list.size() != box_list.size())
        context.malformed("proof.trees", "expected one tree string per chart box");
    std::vector<ChartBox> boxes;
    for (std::size_t k = 0; k < box_list.size(); ++k)
        boxes.push_back(read_chart_box(context, box_list[k], "proof.boxes[" + std::to_string(k) + "]"));
    return {boxes, tree_list};
}

// The sentence: the bound on the domain the boxes cover (the whole chart domain, or the boxes
// alone), with what the replay counted.
std::string critical_lattice_sentence(const mpq_class& p, bool whole, std::size_t box_count, const CriticalBound& bound,
                                      const Real& upper_phi, const TreeCounts& counts, const ClosingRegions& regions) {
    std::string leaves;
    long total = 0;
    for (int r = 0; r < leaf_reasons; ++r) {
        leaves += std::string(r ? ", " : "") + reason_name(static_cast<LeafReason>(r)) + " " + std::to_string(counts.leaves[r]);
        total += counts.leaves[r];
    }
    const std::string where =
        whole ? whole_domain_words(0, box_count)
              : "on the " + count_words(static_cast<long>(box_count), "chart box", "chart boxes") +
                    " of proof.boxes (the chart of NOTES.md 12.2)";
    const std::string which = whole ? "whose chart basis satisfies its configuration"
                                    : "whose chart basis lies in one of these boxes and satisfies the box's configuration, "
                                      "with b1 longest in the max norm among its orbit, a2 <= a3 where v2 and v3 share a face "
                                      "and, for A3, b1 . (b2 + b3) >= |b1|^2 (NOTES.md 12.2),";
    const std::string consequence =
        whole ? std::string(whole_domain_consequence)
              : "so the density of each such packing is at most ";
    return "At p = " + exact_text(p) + ", " + where + ": every lattice packing of the superball K = {|x|^(2p) + |y|^(2p) + " +
           "|z|^(2p) <= 1} " + which + " has |det| >= T >= " + lower_end_words(bound.threshold) + " (claim.data.threshold), " +
           consequence + upper_end_words(upper_phi) + " (the upper end of claim.data.upper_phi, which holds V(K) / T; V(K) in " +
           enclosure_words(bound.volume) + ", " + volume_words + "). The " + count_words(static_cast<long>(box_count), "tree", "trees") +
           " replay " + count_words(counts.nodes, "box", "boxes") + " with " + std::to_string(total) + " leaves (" + leaves +
           "), " + count_words(static_cast<long>(regions.regions.size()), "closing region", "closing regions") + " and " +
           count_words(static_cast<long>(regions.images.size()), "image", "images") + " in the chart.";
}

std::string check_critical_lattice(const Json& claim, Context& context) {
    // The chart's powers |x|^(2p - 1) need 2p > 1 (NOTES.md 12.2).
    const ClaimParts parts = read_claim_parts(claim, context, "critical-lattice", "claim.data.p", "the chart needs p > 1/2");
    const Json &data = parts.data, &inputs = parts.inputs, &proof = parts.proof;
    const mpq_class& p = parts.p;
    const mpfr_prec_t precision = context.precision();

    // 1. T and V(K).
    const CriticalBound bound = read_critical_bound(context, data, p);
    const Real& threshold = bound.threshold;

    // 2. The closing regions.
    const ClosingRegions regions =
        replay_closing_regions(context, context.member(proof, "regions", "proof"), "proof.regions", p, threshold);

    // The start boxes and their trees.
    const StartBoxes start = read_start_boxes(context, proof);
    const std::vector<ChartBox>& boxes = start.boxes;
    const std::string domain = context.string_at(data, "domain", "claim.data");
    if (domain != "whole" && domain != "boxes") context.malformed("claim.data.domain", "expected \"whole\" or \"boxes\"");
    const bool whole = whole_domain(boxes);
    context.require(whole == (domain == "whole"), "claim.data.domain",
                    whole ? "the boxes are the whole chart domain: the domain is \"whole\""
                          : "the boxes are not the 168 top-level boxes of the chart domain, in order: the domain is \"boxes\"");

    // 3. The trees.
    const TreeSetting setting{chart_setting(p, precision), &regions, bound.volume_lo, threshold};
    TreeCounts counts;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        const std::string path = "proof.trees[" + std::to_string(k) + "]";
        if (!start.trees[k].is_string()) context.malformed(path, "expected a tree string");
        context.current_step = path;
        replay_tree(context, start.trees[k].get_ref<const std::string&>(), boxes[k], setting, path, counts);
    }

    // 4. The density bound.
    const Real upper_phi = read_upper_phi(context, data, bound);
    context.rational_at(inputs, "gap", "inputs");  // the producer's gap to the best lattice, informational
    check_p_decimal(context, inputs, p);
    return critical_lattice_sentence(p, whole, boxes.size(), bound, upper_phi, counts, regions);
}

const ClaimKindRegistration registration("critical-lattice", check_critical_lattice);

}  // namespace

}  // namespace superpack_checker
