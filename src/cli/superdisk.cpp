// superpack superdisk --p P [--digits D] [--json] [--certificate FILE]
// superpack superdisk --scan a:b:h --csv
#include <memory>

#include "common.hpp"
#include "output_paths.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/cert/superdisk_certificate.hpp"
#include "superpack/problems/star/star_disk.hpp"
#include "superpack/problems/superdisk/superdisk.hpp"

namespace superpack::cli {

namespace {

struct SuperdiskCliOptions {
    std::string p, digits, scan, certificate;
    bool json = false, csv = false;
};

template <class I>
Json lattice_json(const HexagonLattice<I>& lattice) {
    Json result;
    result["status"] = to_string(lattice.status);
    result["t"] = enclosure_json(lattice.t);
    if (lattice.status != RootStatus::unique) {
        result["reason"] = lattice.reason;
        return result;
    }
    Json basis = Json::array();
    for (const auto& row : lattice.basis) basis.push_back(Json::array({enclosure_json(row[0]), enclosure_json(row[1])}));
    result["basis"] = basis;
    result["determinant"] = enclosure_json(lattice.determinant);
    result["phi"] = enclosure_json(lattice.phi);
    return result;
}

template <class I>
Json proof_json(const SuperdiskReport<I>& report) {
    Json pieces = Json::array();
    for (const auto& piece : report.pieces) {
        Json entry;
        entry["t"] = enclosure_json(piece.t);
        entry["verdict"] = to_string(piece.verdict);
        entry["reason"] = piece.reason;
        if (piece.verdict != PieceVerdict::undecided) {
            entry["lower_bound_D"] = enclosure_json(lower_point(piece.lower_bound));
            entry["v"] = Json::array({enclosure_json(piece.v[0]), enclosure_json(piece.v[1])});
            entry["derivative"] = enclosure_json(piece.derivative);
        }
        pieces.push_back(entry);
    }
    Json proof;
    proof["parameter"] = "u(t) = (1, t) / ||(1, t)||_(2p), t in [0, 1]; v(t) on bd K with v - u on bd K, det(u, v) > 0; "
                         "D(t) = det(u, v); packing determinant 4 D";
    proof["symmetry"] = "D is invariant under the dihedral group of the square, so t in [0, 1] covers every u (NOTES.md 7)";
    proof["upper_bound_witness"] = lattice_json(report.optimal_lattice);
    proof["pieces"] = pieces;
    return proof;
}

template <class I>
Json report_json(const SuperdiskReport<I>& report) {
    Json document;
    document["area"] = enclosure_json(report.area);
    document["lattices"] = {{"Lambda0", lattice_json(report.lambda0)}, {"Lambda1", lattice_json(report.lambda1)}};
    document["status"] = to_string(report.status);
    document["message"] = report.message;
    if (report.status == OptimumStatus::not_applicable) return document;
    if (report.status == OptimumStatus::certified) {
        document["optimal_phi"] = enclosure_json(report.optimal_phi);
        document["optimal_determinant"] = enclosure_json(report.optimal_determinant);
        document["optimal_lattice"] = lattice_json(report.optimal_lattice);
        Json argmin = Json::array();
        for (const auto& component : report.argmin_t) argmin.push_back(enclosure_json(component));
        document["argmin_t"] = argmin;
        document["attained_by"] = report.attained_by;
        Json gap;
        if (report.lambda0.status == RootStatus::unique) gap["Lambda0"] = enclosure_json(report.gap_lambda0);
        if (report.lambda1.status == RootStatus::unique) gap["Lambda1"] = enclosure_json(report.gap_lambda1);
        document["gap"] = gap;
    }
    if (!report.tiling) document["proof"] = proof_json(report);
    return document;
}

const char* const no_optimality = "no optimality claimed: Fejes Toth's theorem and the inscribed-hexagon reduction need a convex disk";

// Below 1/2: the densest lattice the search certifies (problems/star/star_disk.hpp).
template <class I>
Json concave_json(const StarDiskLattice<I>& lattice) {
    Json result{{"status", lattice.status == Outcome::proved ? "certified" : "undecided"},
                {"reason", lattice.reason},
                {"diamond_insertion_phi", enclosure_json(lattice.insertion_phi)},
                {"diamond_insertion", "the square |x| + |y| <= 1 holds the disk and tiles with the lattice (1, 1), (1, -1)"},
                {"candidates_checked", lattice.candidates_checked},
                {"optimality", no_optimality}};
    if (!lattice.phi) return result;
    Json basis = Json::array();
    for (const auto& row : lattice.basis) basis.push_back(Json::array({rational_text(row[0]), rational_text(row[1])}));
    result["basis"] = basis;
    result["phi"] = enclosure_json(*lattice.phi);
    result["start"] = lattice.start;
    return result;
}

template <class I>
void print_concave(const StarDiskLattice<I>& lattice, int digits) {
    auto text = [digits](const I& x) {
        const DecimalEnclosure d = to_decimal(x, digits);
        return "[" + d.lo + ", " + d.hi + "]";
    };
    std::cout << "  diamond insertion phi " << text(lattice.insertion_phi) << "  (the lattice (1, 1), (1, -1))\n";
    if (!lattice.phi) {
        std::cout << "  certified lattice undecided: " << lattice.reason << "\n";
        return;
    }
    std::cout << "  certified lattice phi " << text(*lattice.phi) << "  (from " << lattice.start << ")\n";
    const auto field = field_of(*lattice.phi);
    for (int i = 0; i < 2; ++i)
        std::cout << "  basis e" << i + 1 << "  " << text(field.rational(lattice.basis[i][0])) << ", "
                  << text(field.rational(lattice.basis[i][1])) << "  (exact rationals in --json)\n";
    std::cout << "  note: " << no_optimality << "\n";
}

// Measured (README): the branch and bound at p = 1.25 takes about 34 s at 1000 digits.
constexpr long max_digits = 1000;
// A scan computes one optimum per p, about 0.07 s each in binary64: 1000 values take a minute.
constexpr std::size_t max_scan_values = 1000;

template <class I>
void print_table(const SuperdiskReport<I>& report, const std::string& p, const char* backend, int digits) {
    std::cout << "superdisk |x|^(2p) + |y|^(2p) <= 1 at p = " << p << "  (" << backend << ")\n";
    auto row = [digits](const std::string& name, const I& x) {
        const DecimalEnclosure text = to_decimal(x, digits);
        std::cout << "  " << name << std::string(name.size() < 16 ? 16 - name.size() : 1, ' ') << "[" << text.lo
                  << ", " << text.hi << "]  width " << width_text(x) << "\n";
    };
    row("area", report.area);
    for (const auto* lattice : {&report.lambda0, &report.lambda1}) {
        const std::string name = lattice == &report.lambda0 ? "Lambda0" : "Lambda1";
        if (lattice->status == RootStatus::unique)
            row("phi " + name, lattice->phi);
        else
            std::cout << "  phi " << name << "  undecided: " << lattice->reason << "\n";
    }
    if (report.status == OptimumStatus::certified) {
        row("optimal phi", report.optimal_phi);
        if (report.lambda0.status == RootStatus::unique) row("gap Lambda0", report.gap_lambda0);
        if (report.lambda1.status == RootStatus::unique) row("gap Lambda1", report.gap_lambda1);
        if (!report.tiling) {
            for (const auto& component : report.argmin_t) row("argmin t", component);
            std::cout << "  pieces          " << report.pieces.size() << "\n";
        }
        std::cout << "  attained by     " << report.attained_by << "\n";
    }
    std::cout << "  note: " << report.message << "\n";
}

int run_scan(const SuperdiskCliOptions& options) {
    const std::vector<Rational> values = parse_scan(options.scan, max_scan_values);
    return with_field(options.digits, max_digits, [&](const auto& field, long digits) {
        using I = typename std::decay_t<decltype(field)>::Interval;
        const int print_digits = table_digits(digits, !options.digits.empty());
        auto csv_pair = [print_digits](const I& x) { return csv_enclosure(x, print_digits); };
        std::cout << "p,phi_Lambda0_lo,phi_Lambda0_hi,phi_Lambda1_lo,phi_Lambda1_hi,optimal_phi_lo,optimal_phi_hi,"
                     "attained_by\n";
        int code = exit_ok;
        std::size_t done = 0;
        for (const Rational& p : values) {
            const auto report = decided(within_contract([&] { return analyse_superdisk(p, field); }), field, digits, max_digits);
            auto family = [&](const auto& lattice) { return lattice.status == RootStatus::unique ? csv_pair(lattice.phi) : std::string(","); };
            std::cout << decimal_or_fraction_text(p) << "," << family(report.lambda0) << "," << family(report.lambda1) << ","
                      << (report.status == OptimumStatus::certified ? csv_pair(report.optimal_phi) : std::string(","))
                      << "," << report.attained_by << "\n";
            if (report.status != OptimumStatus::certified) code = exit_undecided;
            if (++done % 20 == 0) std::cerr << "superdisk scan: " << done << " / " << values.size() << "\n";
        }
        if (code != exit_ok) throw Failure(code, "superdisk scan: undecided: some optimum is not certified (empty CSV fields)");
        return code;
    });
}

int run(const SuperdiskCliOptions& options) {
    if (!options.scan.empty()) {
        if (!options.p.empty()) throw Failure(exit_usage, "superdisk: give one of --p and --scan, not both");
        if (!options.csv) throw Failure(exit_usage, "superdisk: --scan needs --csv");
        if (options.json) throw Failure(exit_usage, "superdisk: --scan prints CSV, not --json");
        if (!options.certificate.empty()) throw Failure(exit_usage, "superdisk: --certificate needs --p (one p), not --scan");
        require_rounding_self_test();
        return run_scan(options);
    }
    if (options.csv) throw Failure(exit_usage, "superdisk: --csv needs --scan a:b:h");
    if (options.p.empty()) throw Failure(exit_usage, "superdisk needs --p P or --scan a:b:h --csv");
    const Rational p = parse_p(options.p);
    if (!options.certificate.empty() && p <= Rational(1, 2))
        throw Failure(exit_usage, "superdisk: no certificate for p <= 1/2 (p = 1/2 tiles; below, check-lattice --p P --basis "
                                  "\"u1,u2,0; w1,w2,0; 0,0,2\" --certificate FILE proves the plane lattice, NOTES.md 13.8)");
    require_output_paths({{"--certificate", options.certificate}});
    require_rounding_self_test();
    return with_field(options.digits, max_digits, [&](const auto& field, long digits) {
        const auto report = decided(within_contract([&] { return analyse_superdisk(p, field); }), field, digits, max_digits);
        if (p < Rational(1, 2)) {
            std::cerr << "superdisk: p < 1/2, searching lattices of the concave disk\n";
            const auto lattice = decided(within_contract([&] { return best_star_disk_lattice(p, field); }), field, digits, max_digits);
            if (options.json) {
                Json document = header_json("superdisk", field, digits);
                document["p"] = options.p;
                document["p_exact"] = rational_text(p);
                document.update(report_json(report));
                document["concave_lattice"] = concave_json(lattice);
                print_json(document);
            } else {
                print_table(report, options.p, field.backend(), table_digits(digits, !options.digits.empty()));
                print_concave(lattice, table_digits(digits, !options.digits.empty()));
            }
            if (lattice.status != Outcome::proved) throw Failure(exit_undecided, "superdisk: undecided: " + lattice.reason);
            return exit_ok;
        }
        if (!options.certificate.empty() && report.status == OptimumStatus::certified)
            write_certificate_or_fail(options.certificate, field, digits, max_digits,
                                      [&] { return superdisk_certificate(report, p, field, digits); });
        if (options.json) {
            Json document = header_json("superdisk", field, digits);
            document["p"] = options.p;
            document["p_exact"] = rational_text(p);
            document.update(report_json(report));
            print_json(document);
        } else {
            print_table(report, options.p, field.backend(), table_digits(digits, !options.digits.empty()));
        }
        // p < 1/2 (not applicable): the lattices and the optimum are printed as undecided.
        if (report.status != OptimumStatus::certified)
            throw Failure(exit_undecided, "superdisk: undecided: " + report.message +
                                              (options.digits.empty() && report.status == OptimumStatus::undecided ? "; try --digits 30" : ""));
        return exit_ok;
    });
}

}  // namespace

void add_superdisk(CLI::App& app) {
    auto options = std::make_shared<SuperdiskCliOptions>();
    CLI::App* command = app.add_subcommand(
        "superdisk", "Superdisk: the Lambda0/Lambda1 lattices and the certified optimal packing density (p >= 1/2); below 1/2 "
        "the densest lattice packing superpack certifies (no optimality claim)");
    command->add_option("--p", options->p, std::string("deformation parameter: a decimal (1.25) or a fraction (5/4); ") + supported_p_text);
    add_digits_option(*command, options->digits, max_digits);
    command->add_option("--scan", options->scan,
                        "a:b:h: every p = a, a + h, ..., <= b (with --csv; at most " + std::to_string(max_scan_values) + " values)");
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    command->add_flag("--csv", options->csv, "with --scan: one CSV row per p on stdout");
    add_output_option(*command, "--certificate", options->certificate,
                      "with --p > 1/2: write a certificate of the optimum (replay it with `superpack verify FILE`); "
                      "nothing is written when undecided");
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("superdisk", add_superdisk);
}  // namespace

}  // namespace superpack::cli
