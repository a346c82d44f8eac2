// superpack audit [--family F] [--p-range a:b] [--second-root] [--pieces N] [--depth D] [--json]
//                [--certificate FILE] (one family, the published lattice)
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>

#include "common.hpp"
#include "output_paths.hpp"
#include "superpack/cert/atomic_file.hpp"
#include "superpack/problems/families/audit.hpp"
#include "superpack/cert/audit_certificate.hpp"

namespace superpack::cli {

namespace {

struct AuditOptions {
    std::string family, p_range, output_directory = "out", certificate;
    bool second_root = false, json = false;
    int pieces = 0, depth = -1;  // 0 / -1: the family's default (the options' ranges exclude both)
};

// Limits (README): --pieces and --depth, and AuditSettings::max_pieces for the whole audit.
const int max_initial_pieces = static_cast<int>(AuditSettings{}.max_pieces);
constexpr int max_depth = 30;

// a:b inside the family's domain (a piece outside it would certify a lattice the family does not define).
AuditRange parse_range(const std::string& text, Family family, const AuditRange& claimed) {
    if (text.empty()) return claimed;
    const auto colon = text.find(':');
    if (colon == std::string::npos) throw Failure(exit_usage, "--p-range '" + text + "': expected a:b");
    AuditRange range{parse_p(text.substr(0, colon), "--p-range a"), parse_p(text.substr(colon + 1), "--p-range b"), {},
                     "user range"};
    if (!(range.lo < range.hi)) throw Failure(exit_usage, "--p-range '" + text + "': need a < b");
    for (const Rational& end : {range.lo, range.hi}) {
        try {
            require_in_domain(family, end);
        } catch (const InputError&) {
            throw Failure(exit_usage, "--p-range '" + text + "' is outside the domain of " + to_string(family) + " (" +
                                          family_domain_text(family) + ")");
        }
    }
    for (const Rational& b : claimed.breaks) range.breaks.push_back(b);  // keep p*_o bracketed
    return range;
}

bool undecided(const AuditPiece& piece) { return piece.outcome == "undecided" || piece.outcome == "overlapping_at_point"; }

std::string range_text(const AuditPiece& piece) {
    return "[" + decimal_or_fraction_text(piece.lo) + ", " + decimal_or_fraction_text(piece.hi) + "]";
}

// Writes nothing unless some piece has a certified verdict (exit 4), and nothing half-written (atomic).
void write_audit_certificate(const std::string& path, const AuditResult& result) {
    Contracted<Json> built;
    try {
        built = within_contract([&] { return audit_certificate(result); });
    } catch (const InputError& error) {
        throw Failure(exit_usage, std::string("audit: no certificate written: ") + error.what());
    } catch (const std::runtime_error& error) {
        throw Failure(exit_undecided, std::string("audit: no certificate written: ") + error.what());
    }
    const Json certificate = decided(std::move(built), DoubleField{}, 0, 0);  // the audit has no --digits
    try {
        write_certificate(path, certificate);
    } catch (const std::runtime_error& error) {
        throw Failure(exit_usage, std::string("no certificate written: ") + error.what());
    }
    std::cerr << "audit: certificate " << path << " (" << decided_pieces(certificate) << " of " << result.pieces.size()
              << " pieces with a certified verdict)\n";
}

// The families to audit, after the options' checks, each with its usage error (a step of its
// own: run reads as check, audit each family, report).
std::vector<Family> checked_families(const AuditOptions& options) {
    std::vector<Family> families = options.family.empty() ? all_families() : std::vector{parse_family(options.family)};
    if (options.second_root && (families.size() != 1 || families[0] != Family::O1))
        throw Failure(exit_usage, "--second-root needs --family O1");
    if (!options.certificate.empty() && (families.size() != 1 || options.second_root))
        throw Failure(exit_usage, "--certificate needs one --family and the published lattice (no --second-root)");
    if (!options.p_range.empty() && families.size() != 1)
        throw Failure(exit_usage, "--p-range needs one --family (the families' domains differ)");
    return families;
}

// Each family's range of p: --p-range, or the claimed range ([1/2, 2] for O1's second root)
// (a step of its own, like checked_families).
std::vector<AuditRange> audit_ranges(const AuditOptions& options, const std::vector<Family>& families) {
    std::vector<AuditRange> ranges;
    for (Family family : families) {
        AuditRange range = parse_range(options.p_range, family, claimed_audit_range(family));
        if (options.second_root && options.p_range.empty()) range = {Rational(1, 2), Rational(2), range.breaks, "[1/2, 2]"};
        ranges.push_back(range);
    }
    return ranges;
}

// The file a family's audit is written to, in --output-directory (its own function: the paths
// are checked before the work and written after it).
std::string audit_file(const AuditOptions& options, Family family) {
    const AuditResult named{family, options.second_root ? AuditBranch::o1_second_root : AuditBranch::published, {}, {}, std::nullopt};
    return options.output_directory + "/" + std::filesystem::path(audit_file_name(named)).filename().string();
}

// One family's audit as text: its verdict ranges, one a line (a step of its own: the text
// report, apart from the audit and its files).
void print_audit_text(Family family, const Json& summary, const AuditResult& result, const AuditRange& range, double seconds,
                      const std::string& file) {
    std::cout << to_string(family) << " (" << summary["lattice"].get<std::string>() << "), " << result.pieces.size()
              << " pieces, " << seconds << " s -> " << file << "\n  " << range.note << "\n";
    for (const AuditPiece& piece : merge_verdict_ranges(result.pieces)) {
        std::cout << "  p in " << range_text(piece) << "  " << piece.outcome;
        if (piece.outcome == "packing") std::cout << ", " << piece.contacts << " contacts";
        if (piece.witness)
            std::cout << ", witness (" << (*piece.witness)[0] << ", " << (*piece.witness)[1] << ", "
                      << (*piece.witness)[2] << ")";
        if (piece.outcome == "undecided" || piece.outcome == "overlapping_at_point") std::cout << ": " << piece.reason;
        std::cout << "\n";
    }
}

int run(const AuditOptions& options, bool default_directory) {
    const std::vector<Family> families = checked_families(options);
    const std::vector<AuditRange> ranges = audit_ranges(options, families);
    // Every path is checked before hours of work: the default out/ is created, a named directory must exist.
    if (default_directory) create_default_directory(options.output_directory);
    std::vector<OutputPath> outputs{{"--certificate", options.certificate}};
    for (Family family : families) outputs.push_back({"--output-directory", audit_file(options, family)});
    require_output_paths(outputs);
    require_rounding_self_test();
    Json document = header_json("audit", DoubleField{}, 15);
    Json audits = Json::array();
    std::size_t undecided_pieces = 0;
    for (std::size_t index = 0; index < families.size(); ++index) {
        const Family family = families[index];
        const AuditRange& range = ranges[index];
        AuditSettings settings = default_audit_settings(family);
        if (options.pieces > 0) settings.initial_pieces = options.pieces;
        if (options.depth >= 0) settings.max_depth = options.depth;
        const auto start = std::chrono::steady_clock::now();
        // Binary64 pieces, and the audit has no --digits.
        const AuditResult result = decided(within_contract([&] {
                                               return audit_family(family, range, settings,
                                                                   options.second_root ? AuditBranch::o1_second_root : AuditBranch::published,
                                                                   [](const std::string& line) { std::cerr << "audit: " << line << "\n"; });
                                           }),
                                           DoubleField{}, 0, 0);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string file = audit_file(options, family);
        undecided_pieces += std::count_if(result.pieces.begin(), result.pieces.end(), undecided);
        Json full = header_json("audit", DoubleField{}, 15);
        full.update(audit_json(result));
        write_atomically(file, full.dump(1) + "\n");
        if (!options.certificate.empty()) write_audit_certificate(options.certificate, result);
        const Json summary = audit_json(result);
        audits.push_back(Json{{"family", summary["family"]}, {"lattice", summary["lattice"]}, {"range", summary["range"]},
                              {"range_note", summary["range_note"]}, {"pieces", result.pieces.size()},
                              {"verdict_ranges", summary["verdict_ranges"]}, {"file", file}});
        if (!options.json) print_audit_text(family, summary, result, range, seconds, file);
    }
    if (options.json) {
        document["audits"] = audits;
        document["undecided_pieces"] = undecided_pieces;
        print_json(document);
    }
    // Every piece is accounted for and written, but an undecided piece leaves the audit undecided.
    if (undecided_pieces > 0)
        throw Failure(exit_undecided, "audit: undecided: " + std::to_string(undecided_pieces) +
                                          " piece(s) without a verdict for every p (listed with their reasons)");
    return exit_ok;
}

}  // namespace

void add_audit(CLI::App& app) {
    auto options = std::make_shared<AuditOptions>();
    CLI::App* command = app.add_subcommand("audit", "Certify a family over its claimed p range, piece by piece");
    command->add_option("--family", options->family, "C0, C1, O0, O1, D14 or S6 (default: all; S6 on [0.89, 0.91] by default, any range holding 9/10 with --p-range)");
    command->add_option("--p-range", options->p_range, "a:b exact, inside the family's domain (default: the claimed range); needs --family");
    command->add_flag("--second-root", options->second_root, "O1: audit the lattice of the other real root of Eq. (12)");
    command->add_option("--pieces", options->pieces,
                        "initial pieces per range, 1 to " + std::to_string(max_initial_pieces) + " (default 16; O1: 300; D14: 32)")
        ->check(CLI::Range(1, max_initial_pieces));
    command->add_option("--depth", options->depth,
                        "bisections of an undecided piece, 0 to " + std::to_string(max_depth) + " (default 12; O1: 3; D14: 12); at most " +
                            std::to_string(AuditSettings{}.max_pieces) + " pieces in all")
        ->check(CLI::Range(0, max_depth));
    CLI::Option* directory = add_output_option(*command, "--output-directory", options->output_directory,
                                               "an existing directory for audit-<family>.json (default out, created if missing)");
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    add_output_option(*command, "--certificate", options->certificate,
                      "with one --family: write a certificate of the piece verdicts (replay it with `superpack verify FILE`)");
    command->callback([options, directory] { run(*options, directory->count() == 0); });
}

namespace {
const SubcommandRegistration registration("audit", add_audit);
}  // namespace

}  // namespace superpack::cli
