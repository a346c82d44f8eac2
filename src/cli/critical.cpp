// superpack critical --p P [--gap G] [--threads N] [--shard i/n] [--max-boxes M] [--around R]
//                    [--certificate FILE] [--json]
// superpack critical --merge FILE... [--json]
// superpack critical --cover CERTIFICATE... --split K --certificate FILE [--threads N] [--json]
// A certified upper bound on the lattice packing density at p (problems/critical/critical.hpp, NOTES 12),
// run whole or in shards whose JSON documents --merge sums into the whole domain's result.
#include <chrono>
#include <filesystem>
#include <memory>

#include "common.hpp"
#include "output_paths.hpp"
#include "superpack/arith/enclosure_json.hpp"
#include "superpack/cert/critical_certificate.hpp"
#include "superpack/cert/critical_shards.hpp"
#include "superpack/problems/critical/critical.hpp"

namespace superpack::cli {

namespace {

struct CriticalCommandOptions {
    std::string p, gap = "0", shard = "0/1", around, certificate;
    std::vector<std::string> merge, cover;
    int threads = 1, split = 0;
    long max_boxes = 50000000;
    bool json = false;
};

constexpr int max_threads = 64;
constexpr long max_box_budget = 2000000000;

void require_threads(int threads) {
    if (threads < 1 || threads > max_threads)
        throw InputError("--threads: 1 to " + std::to_string(max_threads) + ", got " + std::to_string(threads));
}

// --shard i/n with 0 <= i < n <= the number of start boxes.
std::pair<int, int> parse_shard(const std::string& text, long start_boxes) {
    const std::size_t slash = text.find('/');
    const std::string limit = "--shard: i/n with 0 <= i < n <= " + std::to_string(start_boxes) + " (the start boxes)";
    if (slash == std::string::npos || text.size() > 20) throw InputError(limit + ", got \"" + text.substr(0, 20) + "\"");
    try {
        std::size_t used_i = 0, used_n = 0;
        const int i = std::stoi(text.substr(0, slash), &used_i);
        const int n = std::stoi(text.substr(slash + 1), &used_n);
        if (used_i != slash || used_n != text.size() - slash - 1 || i < 0 || n < 1 || i >= n || n > start_boxes)
            throw InputError(limit + ", got \"" + text + "\"");
        return {i, n};
    } catch (const std::logic_error&) {
        throw InputError(limit + ", got \"" + text + "\"");
    }
}

Json box_json(const ChartBox<DInterval>& box) {
    Json x = Json::array();
    for (const DInterval& value : box.x) x.push_back(enclosure_json(value));
    return {{"configuration", configuration_name(box.configuration)}, {"face2", box.face2}, {"face3", box.face3}, {"x", x},
            {"depth", box.depth}};
}

// `bound_suffix` follows the names of the two fields that state the bound: "" on the whole
// domain, and on given boxes (--around) what they are, since the bound holds on them only.
Json result_json(const CriticalResult<DInterval>& result, const std::string& bound_suffix) {
    Json counts = Json::object();
    for (int r = 0; r < box_reasons; ++r) counts[box_reason_name(static_cast<BoxReason>(r))] = result.counts[r];
    Json regions = Json::array();
    for (const ClosingRegion<DInterval>& region : result.regions)
        regions.push_back({{"verdict", region.verdict == Outcome::proved ? "proved" : "undecided"},
                           {"reason", region.reason},
                           {"radius", region.radius},
                           {"rho", region.rho},
                           {"determinant", enclosure_json(region.determinant)}});
    Json undecided = Json::array();
    for (const UndecidedBox<DInterval>& box : result.undecided) {
        Json item = box_json(box.box);
        item["reason"] = box_reason_name(box.reason);
        undecided.push_back(item);
    }
    Json basis = Json::array();
    for (const auto& row : result.reference.basis)
        basis.push_back(Json::array({enclosure_json(row[0]), enclosure_json(row[1]), enclosure_json(row[2])}));
    return {{"status", result.status == Outcome::proved ? "proved" : "undecided"},
            {"message", result.message},
            {"lower", {{"lattice", result.reference.name}, {"phi", enclosure_json(result.reference.phi)}, {"basis", basis}}},
            {"upper" + bound_suffix, {{"phi", enclosure_json(result.upper_phi)}}},
            {"relative_gap", enclosure_json(result.relative_gap)},
            {"threshold" + bound_suffix, enclosure_json(result.threshold)},
            {"volume", enclosure_json(result.volume)},
            {"boxes", counts},
            {"processed", result.processed},
            {"start_boxes", result.start_boxes},
            {"regions", regions},
            {"images", result.images.size()},
            {"undecided_examples", undecided},
            {"seconds", result.seconds}};
}

void print_table(const CriticalResult<DInterval>& result, const CriticalOptions& options, bool merged) {
    const DecimalEnclosure lower = to_decimal(result.reference.phi, 17);
    const DecimalEnclosure upper = to_decimal(result.upper_phi, 17);
    const DecimalEnclosure gap = to_decimal(result.relative_gap, 3);
    const DecimalEnclosure threshold = to_decimal(result.threshold, 17);
    // A part of the domain (a shard, or --around's boxes) bounds the lattice packings in it only.
    const std::string part = options.around > 0      ? " in the boxes around the images"
                             : result.partial_domain ? " in this shard's start boxes"
                                                     : "";
    std::cout << "p            " << decimal_or_fraction_text(options.p) << "\n"
              << "lower        phi in [" << lower.lo << ", " << lower.hi << "]  " << result.reference.name
              << " (the densest certified lattice packing, superpack best)\n"
              << "upper        phi <= " << upper.hi << (part.empty() ? "" : " for the lattice packings" + part + " only")
              << (result.status == Outcome::proved ? "" : "  (not proved)") << "\n"
              << "gap          upper / lower - 1 <= " << gap.hi << "\n"
              << "threshold    |det| >= " << threshold.lo << " for every lattice packing" << part
              << (result.status == Outcome::proved ? "" : " (not proved)") << "\n";
    if (options.around > 0)
        std::cout << "domain       " << result.start_boxes << " chart boxes around the best lattice's images (--around): the "
                  << "bound holds on them only\n";
    else if (result.partial_domain)
        std::cout << "domain       shard " << options.shard << "/" << options.shards << ": " << result.start_boxes << " of "
                  << (static_cast<long>(top_level_boxes) << options.split) << " start boxes (the bound needs every shard)\n";
    std::cout << "status       " << (result.status == Outcome::proved ? "proved" : "undecided") << ": " << result.message << "\n"
              << "boxes        " << result.processed << " evaluated; leaves:";
    for (int r = 0; r < box_reasons; ++r)
        if (result.counts[r] > 0) std::cout << " " << box_reason_name(static_cast<BoxReason>(r)) << " " << result.counts[r];
    std::cout << "\n";
    for (const ClosingRegion<DInterval>& region : result.regions)
        std::cout << "region       " << (region.verdict == Outcome::proved ? "proved" : "undecided") << ": " << region.reason
                  << (region.verdict == Outcome::proved ? ", radius " + std::to_string(region.radius) : std::string()) << ", "
                  << result.images.size() << " images in the chart\n";
    if (merged)
        std::cout << "time         " << result.seconds << " s, the shards' wall times summed\n";
    else
        std::cout << "time         " << result.seconds << " s on " << options.threads << (options.threads == 1 ? " thread\n" : " threads\n");
}

// A merged result (merged true) has no threads or budget of its own: its time is the shards'.
void print_result(const CriticalResult<DInterval>& result, const CriticalOptions& options, const std::string& p_text,
                  bool merged, bool json) {
    if (json) {
        const DoubleField field;
        Json document = header_json("critical", field, 15);
        document["p"] = p_text;
        document["p_exact"] = rational_text(options.p);
        document["gap"] = rational_text(options.gap);
        if (merged) {
            document["merged"] = true;
        } else {
            document["threads"] = options.threads;
            document["max_boxes"] = options.max_boxes;
        }
        // What a merge needs: the shard, the domain's size, and T. A run on given boxes (--around)
        // is no shard, and --merge refuses it.
        if (options.around > 0)
            document["domain"] = "around the best lattice's images";
        else
            document["shard"] = {{"index", options.shard}, {"count", options.shards}, {"top_level_boxes", top_level_boxes},
                                 {"split", options.split}};
        document.update(result_json(result, options.around > 0 ? "_around_images" : ""));
        print_json(document);
    } else {
        print_table(result, options, merged);
    }
    if (result.status != Outcome::proved) throw Failure(exit_undecided, "critical: undecided: " + result.message);
}

// --merge: the setup recomputed from the shards' p and gap (each shard's T must print as its
// T does), then the shards' leaves summed.
void run_merge(const CriticalCommandOptions& command) {
    if (!command.p.empty() || command.shard != "0/1")
        throw InputError("critical --merge: takes p, the gap and the shards from the files; give no --p or --shard");
    // A merge re-runs no box, so it has no trees to certify (NOTES.md 12.7) and no boxes to place.
    if (!command.certificate.empty() || !command.around.empty() || command.split != 0)
        throw InputError("critical --merge: writes no certificate and takes no --around or --split (it re-runs no box; the "
                         "split is the shards')");
    std::vector<ShardDocument> documents;
    std::vector<ShardSummary> summaries;
    for (const std::string& path : command.merge) {
        documents.push_back(read_shard_document(path));
        summaries.push_back(documents.back().summary);
        if (documents.back().p_exact != documents.front().p_exact || documents.back().gap != documents.front().gap)
            throw InputError("critical --merge: '" + path + "' has another p or gap than '" + command.merge.front() + "'");
    }
    require_shard_cover(summaries);
    CriticalOptions options;
    options.p = parse_p(documents.front().p_exact, "p_exact of " + command.merge.front());
    options.gap = parse_number(documents.front().gap, "gap of " + command.merge.front());
    require_critical_domain(options.p, options.gap);
    std::cerr << "critical --merge: certifying the densest lattice at p (best) to recompute T\n";
    const CriticalResult<DInterval> setup =
        decided_in_binary64([&] { return critical_setup(critical_reference(options.p, DoubleField{}), options); });
    const Json threshold = enclosure_json(setup.threshold);
    for (std::size_t k = 0; k < documents.size(); ++k)
        if (documents[k].threshold != threshold)
            throw InputError("critical --merge: '" + command.merge[k] + "' has another T than this superpack computes at its p and gap");
    print_result(decided_in_binary64([&] { return merge_shards(setup, summaries); }), options, documents.front().p_exact, true,
                 command.json);
}

// --cover: the shards' certificates named by one cover certificate, which the checker replays in
// full (all of them, on --threads) before it is written.
void run_cover(const CriticalCommandOptions& command) {
    if (!command.p.empty() || command.shard != "0/1" || !command.around.empty() || !command.merge.empty())
        throw InputError("critical --cover: takes p, the gap and T from the certificates; give no --p, --shard, --around or "
                         "--merge (only the shards' --split)");
    require_split(command.split);
    if (command.certificate.empty()) throw InputError("critical --cover: --certificate FILE is required (the cover to write)");
    require_threads(command.threads);
    const CoverParts parts = read_cover_parts(command.cover, command.certificate, command.split);
    std::cerr << "critical --cover: replaying the " << parts.names.size() << " certificates with the checker on "
              << command.threads << (command.threads == 1 ? " thread\n" : " threads\n");
    const std::string directory = std::filesystem::absolute(command.certificate).parent_path().string();
    const Json document = decided_in_binary64([&] { return critical_cover_certificate(parts, directory, command.threads); });
    write_certificate(command.certificate, document);
    const std::string claim = document["claim"]["text"].get<std::string>();
    if (command.json) {
        const DoubleField field;
        Json out = header_json("critical", field, 15);
        out["cover"] = {{"files", parts.names.size()}, {"split", parts.split}, {"certificate", command.certificate}};
        out["claim"] = claim;
        print_json(out);
    } else {
        std::cout << "cover        " << parts.names.size() << " certificates at --split " << parts.split
                  << ", replayed by the checker: " << command.certificate << "\n"
                  << "claim        " << claim << "\n";
    }
}

// --around R: 0 < R <= 1/100, checked before any computation.
double parse_around(const std::string& text) {
    const Rational radius = parse_number(text, "--around");
    if (!(radius > Rational(0)) || radius > Rational(1, 100)) throw InputError("--around: 0 < R <= 1/100, got " + text);
    // The half-width only places the boxes, which the result and the certificate state exactly.
    return std::stod(text);
}

int run(const CriticalCommandOptions& command) {
    require_output_paths({{"--certificate", command.certificate}});
    if (!command.cover.empty()) {
        run_cover(command);
        return exit_ok;
    }
    if (!command.merge.empty()) {
        run_merge(command);
        return exit_ok;
    }
    if (command.p.empty()) throw InputError("critical: --p is required (or --merge FILE...)");
    CriticalOptions options;
    options.p = parse_p(command.p);
    options.gap = parse_number(command.gap, "--gap");
    require_critical_domain(options.p, options.gap);
    require_threads(command.threads);
    if (command.max_boxes < 1 || command.max_boxes > max_box_budget)
        throw InputError("--max-boxes: 1 to " + std::to_string(max_box_budget) + ", got " + std::to_string(command.max_boxes));
    options.threads = command.threads;
    options.max_boxes = command.max_boxes;
    require_split(command.split);
    if (command.split != 0 && !command.around.empty()) throw InputError("critical: --split and --around exclude each other");
    options.split = command.split;
    std::tie(options.shard, options.shards) = parse_shard(command.shard, static_cast<long>(top_level_boxes) << options.split);
    options.around = command.around.empty() ? 0 : parse_around(command.around);
    const DoubleField field;
    std::cerr << "critical: certifying the densest lattice at p (best)\n";
    const CriticalReference<DInterval> reference = decided_in_binary64([&] { return critical_reference(options.p, field); });
    options.record_trees = !command.certificate.empty();
    options.progress = [](const CriticalProgress& progress) {
        std::cerr << "critical: " << progress.seconds << " s, " << progress.processed << " boxes evaluated, "
                  << progress.queued << " queued, " << progress.counts[static_cast<int>(BoxReason::determinant)]
                  << " closed by det, " << progress.counts[static_cast<int>(BoxReason::undecided_width)] +
                                               progress.counts[static_cast<int>(BoxReason::undecided_budget)]
                  << " undecided\n";
    };
    const CriticalResult<DInterval> result = decided_in_binary64([&] { return critical_bound(reference, options); });
    if (!command.certificate.empty() && result.status == Outcome::proved) {
        std::cerr << "critical: replaying the certificate with the checker\n";
        write_certificate(command.certificate, decided_in_binary64([&] { return critical_certificate(result, options); }));
    }
    print_result(result, options, command.p, false, command.json);
    return exit_ok;
}

void add_critical(CLI::App& app) {
    auto options = std::make_shared<CriticalCommandOptions>();
    CLI::App* command = app.add_subcommand(
        "critical", "A certified upper bound on the lattice packing density at p (branch and bound over Minkowski's configurations)");
    command->add_option("--p", options->p, "deformation parameter 1/2 < p <= 10: a decimal or a fraction (required unless --merge)");
    command->add_option("--gap", options->gap,
                        "relative gap 0 <= G < 1/2 and G <= 1 - phi of the best lattice at p (T >= V(K); 0.13 at p = 2): "
                        "prove |det| >= T = (1 - G) |det| of the best lattice (default 0)");
    command->add_option("--threads", options->threads, "worker threads, 1 to " + std::to_string(max_threads) + " (default 1)");
    command->add_option("--shard", options->shard,
                        "i/n: only the start boxes whose index is i mod n (0 <= i < n <= the start boxes, " +
                            std::to_string(top_level_boxes) + " * 2^K at --split K; default 0/1)");
    command->add_option("--split", options->split,
                        "K: bisect each of the " + std::to_string(top_level_boxes) + " top-level boxes K times first (0 to " +
                            std::to_string(max_split) + ", default 0), for shards whose certificates stay small");
    command->add_option("--max-boxes", options->max_boxes,
                        "boxes evaluated at most, 1 to " + std::to_string(max_box_budget) +
                            " (default 5e7); the rest stay undecided");
    command->add_option("--merge", options->merge,
                        "FILE...: the --json documents of shards 0/n to n-1/n (same p and gap), summed into the whole "
                        "domain's result (proved iff every shard is; each file at most 1 MiB)");
    command->add_option("--cover", options->cover,
                        "CERTIFICATE...: the critical-lattice certificates of all shards of one run at --split K (same "
                        "p and gap, in one directory; a shard too large may be replaced by the shards of its start "
                        "boxes' halves at K + 1 or more): write the cover certificate (--certificate FILE, same "
                        "directory) that proves the bound on the whole domain; the checker replays every shard first");
    command->add_option("--around", options->around,
                        "R: instead of the whole domain, the chart boxes of half-width 0 < R <= 1/100 around the images "
                        "of the best lattice's closing region");
    add_output_option(*command, "--certificate", options->certificate,
                      "FILE: write the critical-lattice certificate (every tree, replayed by the checker first; at "
                      "most 256 MiB: --around, or a shard at --split K, whose certificates --cover joins)");
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    command->callback([options] { run(*options); });
}

const SubcommandRegistration registration("critical", add_critical);

}  // namespace

}  // namespace superpack::cli
