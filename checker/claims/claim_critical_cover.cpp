// Claim kind "critical-lattice-cover" (written by `superpack critical --cover`; NOTES.md 12.9):
// the bound of a critical-lattice claim on the whole chart domain, from critical-lattice
// certificates too large for one file. proof.files names them, by file name in this
// certificate's directory. The claim holds when
//   1. every named file is a valid critical-lattice certificate (each replayed here in full by
//      verify_document, several at once on the threads allowed);
//   2. all are at this certificate's p, T and gap;
//   3. their start boxes tile the chart domain split K times (chart_domain, K = claim.data.split):
//      each box of it is a start box, or its two halves by the same rule are each tiled so, at
//      most max_cover_depth halvings deeper; every start box is met once and lies in one file;
//   4. V(K) and V(K) / T are enclosed as in a critical-lattice claim.
// Then every lattice packing of K whose chart basis satisfies its configuration has |det| >= T,
// on every start box, so on the whole domain. A part is never itself a cover.
//
// Keys read: claim.data {p, threshold, volume, upper_phi, split}; inputs {p, p_decimal, gap};
// proof {kind, files}.
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "checker/claims/claim_parts.hpp"
#include "checker/claims/critical_claim.hpp"
#include "checker/claims/critical_tree.hpp"
#include "checker/claims/literature.hpp"
#include "checker/core/limits.hpp"
#include "checker/core/render.hpp"

namespace superpack_checker {

namespace {

// One named file, replayed: its report and, when valid, what the cover compares.
struct Part {
    bool readable = false;
    std::string kind;
    VerifyReport report;
    mpq_class p, gap;
    Real threshold{min_precision};
    std::vector<DomainBox> boxes;
    std::string failure;  // a reading failure, or a value the cover needs that the part lacks
};

// `inner` within `outer`: the same configuration and faces, and every coordinate's range inside.
bool contains(const DomainBox& outer, const DomainBox& inner) {
    if (outer.configuration != inner.configuration || outer.face2 != inner.face2 || outer.face3 != inner.face3) return false;
    for (int k = 0; k < chart_dimension; ++k)
        if (inner.ends[2 * k] < outer.ends[2 * k] || outer.ends[2 * k + 1] < inner.ends[2 * k + 1]) return false;
    return true;
}

// A file name in the cover's directory: no directory part, no "." or "..".
bool plain_name(const std::string& name) {
    return !name.empty() && name.size() <= 255 && name != "." && name != ".." && name.find('/') == std::string::npos &&
           name.find('\0') == std::string::npos;
}

Part replay_part(const std::string& file) {
    Part part;
    const JsonReading reading = read_certificate_file(file);
    if (!reading.ok) {
        part.failure = reading.message + (reading.path.empty() ? "" : " at " + reading.path);
        return part;
    }
    part.readable = true;
    const Json& document = reading.document;
    // The kind before the replay: a cover among the parts is refused without replaying it.
    if (document.is_object() && document.contains("claim") && document["claim"].is_object() &&
        document["claim"].contains("kind") && document["claim"]["kind"].is_string())
        part.kind = document["claim"]["kind"].get<std::string>();
    if (part.kind != "critical-lattice") return part;
    part.report = verify_document(document);
    if (part.report.verdict != Verdict::valid) return part;
    try {
        Context context(document, min_precision);
        const Json& claim = context.member(document, "claim", "");
        const Json& data = context.member(claim, "data", "claim");
        part.p = context.rational_at(data, "p", "claim.data");
        part.threshold = context.interval(context.member(data, "threshold", "claim.data"), "claim.data.threshold");
        part.gap = context.rational_at(context.member(document, "inputs", ""), "gap", "inputs");
        const Json& boxes = context.member(context.member(document, "proof", ""), "boxes", "proof");
        for (std::size_t k = 0; k < boxes.size(); ++k)
            part.boxes.push_back(domain_box(read_chart_box(context, boxes[k], "proof.boxes[" + std::to_string(k) + "]")));
    } catch (const Rejection& rejection) {
        part.failure = "a verified part unreadable at " + rejection.path + ": " + rejection.message;
    }
    return part;
}

// Each file replayed once, `threads` at a time; the first failure (in file order) stops new ones.
std::vector<Part> replay_parts(const std::string& directory, const std::vector<std::string>& names, int threads) {
    std::vector<Part> parts(names.size());
    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> failed{false};
    std::mutex output;
    auto work = [&] {
        for (std::size_t k = next++; k < names.size() && !failed; k = next++) {
            parts[k] = replay_part(directory + "/" + names[k]);
            const Part& part = parts[k];
            if (!part.failure.empty() || part.kind != "critical-lattice" || part.report.verdict != Verdict::valid) failed = true;
            const std::lock_guard<std::mutex> lock(output);
            std::cerr << "superpack-verify: critical-lattice-cover: " + std::to_string(++done) + " of " +
                             std::to_string(names.size()) + " files replayed (" + names[k] + ")\n";
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& thread : pool) thread.join();
    return parts;
}

// The names of proof.files, read and checked before any file is opened: plain names in the
// cover's directory, each once, at most max_cover_files.
std::vector<std::string> read_file_names(Context& context, const Json& proof) {
    context.current_step = "proof.files";
    const Json& files = context.member(proof, "files", "proof");
    if (!files.is_array() || files.empty()) context.malformed("proof.files", "expected a non-empty array of file names");
    if (files.size() > max_cover_files)
        context.malformed("proof.files", std::to_string(files.size()) + " files exceed the limit of " +
                                             std::to_string(max_cover_files) + " (max_cover_files)");
    std::vector<std::string> names;
    std::set<std::string> distinct;
    for (std::size_t k = 0; k < files.size(); ++k) {
        const std::string at = "proof.files[" + std::to_string(k) + "]";
        if (!files[k].is_string() || !plain_name(files[k].get<std::string>()))
            context.malformed(at, "expected a file name in the certificate's directory (no '/', not . or ..)");
        names.push_back(files[k].get<std::string>());
        if (!distinct.insert(names.back()).second) context.reject(at, "the file " + names.back() + " is named twice");
    }
    return names;
}

// Every named file is in the directory and a regular file before the first replay, so that a
// missing part is found at once, not after the others' replays (minutes). symlink_status: a
// symbolic link is refused, never followed.
void require_part_files(Context& context, const std::string& directory, const std::vector<std::string>& names) {
    for (std::size_t k = 0; k < names.size(); ++k) {
        std::error_code error;
        const std::filesystem::file_status status = std::filesystem::symlink_status(directory + "/" + names[k], error);
        const std::string problem = status.type() == std::filesystem::file_type::not_found ? "no such file"
                                    : error                                             ? error.message()
                                    : std::filesystem::is_symlink(status)               ? "a symbolic link, which is not followed"
                                    : !std::filesystem::is_regular_file(status)         ? "not a regular file"
                                                                                        : "";
        context.require(problem.empty(), "proof.files[" + std::to_string(k) + "]", "cannot read " + names[k] + ": " + problem);
    }
}

// A part (proof.files[k], path `at`) must have been replayed, be a valid critical-lattice
// certificate, and be at the cover's p, gap and T; its replay's steps count as the cover's.
void require_part_fits(Context& context, const Part& part, const std::string& at, const std::string& name,
                       const mpq_class& p, const mpq_class& gap, const CriticalBound& bound) {
    context.require(part.readable || !part.failure.empty(), at, "not replayed: an earlier file failed");
    context.require(part.failure.empty(), at, name + ": " + part.failure);
    context.require(part.kind == "critical-lattice", at,
                    name + " is a \"" + part.kind + "\" certificate, not \"critical-lattice\"");
    const VerifyReport& report = part.report;
    context.require(report.verdict == Verdict::valid, at,
                    name + " is " + to_string(report.verdict) + (report.path.empty() ? "" : " at " + report.path) + ": " +
                        report.message);
    context.count_steps(report.steps);
    context.require(part.p == p, at, name + " is at p = " + exact_text(part.p) + ", not " + exact_text(p));
    context.require(part.gap == gap, at, name + " was made at another gap");
    context.require(mpfr_equal_p(part.threshold.lo(), bound.threshold.lo()) != 0, at, name + " proves another T");
}

// The start boxes of all parts, placed on their paths of halvings from the domain.
struct StartBoxes {
    std::map<DomainBox, std::pair<std::size_t, bool>> owner;  // start box -> its file, and whether the walk met it
    std::set<DomainBox> interior;                              // halved on the way to some start box
    std::size_t count = 0;
};

// Places start box `box` of file k (`which` names it): met in no other file, and reached from a
// box of the unsplit domain by halvings of the split rule, at least `split` and at most
// split + max_cover_depth of them; the boxes halved on the way past `split` are interior.
void place_start_box(Context& context, const DomainBox& box, std::size_t k, const std::string& at, const std::string& which,
                     const std::vector<std::string>& names, const std::vector<DomainBox>& top, int split,
                     StartBoxes& start_boxes) {
    const auto placed = start_boxes.owner.emplace(box, std::make_pair(k, false));
    context.require(placed.second, at, which + " is also a start box of " + names[placed.first->second.first]);
    ++start_boxes.count;
    const auto root = std::find_if(top.begin(), top.end(), [&](const DomainBox& t) { return contains(t, box); });
    context.require(root != top.end(), at, which + " is not in the chart domain");
    DomainBox node = *root;
    int depth = 0;
    while (!(node == box)) {
        context.require(depth < split + max_cover_depth, at, which + " is not a box of the domain halved by the split rule");
        if (depth >= split) start_boxes.interior.insert(node);
        const std::array<DomainBox, 2> two = halves(node);
        const bool lower = contains(two[0], box);
        context.require(lower || contains(two[1], box), at, which + " straddles a halving of the split rule");
        node = two[lower ? 0 : 1];
        ++depth;
    }
    context.require(depth >= split, at,
                    which + " is larger than a box of the chart domain split " + std::to_string(split) + " times");
}

// Every box of the split domain is a start box or the union of its halves' covers, and every
// start box is met by that walk (one it did not meet lies inside another start box).
void require_domain_tiled(Context& context, int split, const std::vector<std::string>& names, StartBoxes& start_boxes) {
    context.current_step = "proof.files";
    const std::vector<DomainBox> domain = chart_domain(split);
    for (std::size_t k = 0; k < domain.size(); ++k) {
        std::vector<DomainBox> stack{domain[k]};
        while (!stack.empty()) {
            const DomainBox node = stack.back();
            stack.pop_back();
            const auto found = start_boxes.owner.find(node);
            if (found != start_boxes.owner.end()) {
                found->second.second = true;
                continue;
            }
            context.require(start_boxes.interior.count(node) != 0, "proof.files",
                            "start box " + std::to_string(k) + " of the split domain (" + domain_box_text(domain[k]) +
                                ") is not covered: its piece " + domain_box_text(node) + " is in no file");
            const std::array<DomainBox, 2> two = halves(node);
            stack.push_back(two[1]);
            stack.push_back(two[0]);
        }
    }
    for (const auto& entry : start_boxes.owner)
        context.require(entry.second.second, "proof.files[" + std::to_string(entry.second.first) + "]",
                        names[entry.second.first] + "'s start box (" + domain_box_text(entry.first) +
                            ") lies inside another file's start box");
}

std::string check_critical_cover(const Json& claim, Context& context) {
    const ClaimParts claim_parts =
        read_claim_parts(claim, context, "critical-lattice-cover", "claim.data.p", "the chart needs p > 1/2");
    const Json &data = claim_parts.data, &inputs = claim_parts.inputs, &proof = claim_parts.proof;
    const mpq_class& p = claim_parts.p;
    const CriticalBound bound = read_critical_bound(context, data, p);
    const int split =
        static_cast<int>(read_integer(context, context.member(data, "split", "claim.data"), "claim.data.split", 0, max_domain_split));
    const mpq_class gap = context.rational_at(inputs, "gap", "inputs");
    check_p_decimal(context, inputs, p);

    const std::vector<std::string> names = read_file_names(context, proof);
    const std::string& directory = context.settings().directory;
    if (directory.empty())
        context.malformed("proof.files", "a cover names files in its directory: verify it as a file (superpack verify FILE)");

    require_part_files(context, directory, names);
    // 1-3. Every part replayed and compared; each of its start boxes placed on its path of halvings
    // from a box of the split domain.
    const std::vector<Part> parts = replay_parts(directory, names, std::max(1, context.settings().threads));
    const std::vector<DomainBox> top = chart_domain(0);
    StartBoxes start_boxes;
    for (std::size_t k = 0; k < names.size(); ++k) {
        const std::string at = "proof.files[" + std::to_string(k) + "]", name = names[k];
        context.current_step = at;
        const Part& part = parts[k];
        require_part_fits(context, part, at, name, p, gap, bound);
        for (std::size_t j = 0; j < part.boxes.size(); ++j) {
            const std::string which =
                name + "'s start box " + std::to_string(j) + " (" + domain_box_text(part.boxes[j]) + ")";
            place_start_box(context, part.boxes[j], k, at, which, names, top, split, start_boxes);
        }
    }
    require_domain_tiled(context, split, names, start_boxes);

    // 4. The density bound.
    const Real upper_phi = read_upper_phi(context, data, bound);
    return "At p = " + exact_text(p) + ", " + whole_domain_words(split, start_boxes.count) + ", replayed in the " +
           std::to_string(names.size()) +
           " critical-lattice certificates of proof.files (each valid, all at this p, gap and T, their start boxes these " +
           std::to_string(start_boxes.count) + " boxes, each in exactly one file): every lattice packing of the superball K = " +
           "{|x|^(2p) + |y|^(2p) + |z|^(2p) <= 1} whose chart basis satisfies its configuration has |det| >= T >= " +
           lower_end_words(bound.threshold) + " (claim.data.threshold), " + whole_domain_consequence +
           upper_end_words(upper_phi) + " (the upper end of claim.data.upper_phi, which holds V(K) / T; V(K) in " +
           enclosure_words(bound.volume) + ", " + volume_words + ").";
}

const ClaimKindRegistration registration("critical-lattice-cover", check_critical_cover);

}  // namespace

}  // namespace superpack_checker
