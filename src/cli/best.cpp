// superpack best --p P [--digits D] [--json] [--certificate FILE] [--seed S] [--starts N]
// superpack best --scan a:b:h [--csv] [--plot FILE.png] [--digits D] [--seed S] [--starts N]
// The densest lattice packing of the superball at p that superpack certifies (problems/best/best.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "common.hpp"
#include "output_paths.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/cert/certificate.hpp"
#include "superpack/cert/family_certificate.hpp"
#include "superpack/cert/local_optimum_certificate.hpp"
#include "superpack/cert/star_lattice_certificate.hpp"
#include "superpack/problems/best/best.hpp"
#include "superpack/render/plot.hpp"

namespace superpack::cli {

namespace {

struct BestCommandOptions {
    std::string p, digits, certificate, scan, plot;
    std::uint32_t seed = 1;
    int starts = 16;
    bool json = false, csv = false;
};

// Measured: 1 to 3 s in binary64 (the search); with --digits 1000, 86 s at p = 0.6 on the loaded
// 2-core machine (D14's root search at that precision), 3 s at p = 2.
constexpr long max_digits = 1000;
constexpr int max_starts = 1000;
// A scan row takes about 1 to 5 s above p = 1/2 and 1 to 25 s below, but 3.5 min at p = 1/10
// (NOTES.md 13.6): 200 rows are at most a quarter of an hour above 1/2 and some hours crowded
// near 1/10; each row's start is a progress line on stderr.
constexpr std::size_t max_scan_values = 200;

Json triples_json(const std::vector<Coefficients>& triples) {
    Json list = Json::array();
    for (const Coefficients& c : triples) list.push_back(coefficients_json(c));
    return list;
}

template <class I>
Json basis_json(const Basis<I>& basis) {
    Json rows = Json::array();
    for (const auto& row : basis) rows.push_back(Json::array({enclosure_json(row[0]), enclosure_json(row[1]), enclosure_json(row[2])}));
    return rows;
}

// Each family proved a packing at p against the best (compare_families): beats or ties, with
// the reason of a tie.
template <class I>
Json comparison_json(const BestLattice<I>& best) {
    Json list = Json::array();
    for (const FamilyComparison<I>& comparison : compare_families(best)) {
        const FamilyEntry<I>& entry = *comparison.entry;
        Json item{{"family", to_string(entry.lattice.family)}, {"phi", enclosure_json(*entry.lattice.phi)},
                  {"gap", enclosure_json(comparison.gap)}};
        item["relation"] = comparison.relation == FamilyRelation::beats ? "beats" : "ties";
        if (comparison.relation == FamilyRelation::ties) item["reason"] = comparison.reason;
        list.push_back(item);
    }
    return list;
}

template <class I>
Json not_packings_json(const BestLattice<I>& best) {
    Json list = Json::array();
    for (const FamilyEntry<I>& entry : best.families) {
        if (entry.check.verdict == Outcome::proved) continue;
        list.push_back({{"family", to_string(entry.lattice.family)},
                        {"verdict", entry.lattice.status == Outcome::proved ? packing_word(entry.check.verdict) : "no lattice"},
                        {"reason", entry.lattice.status == Outcome::proved ? entry.check.reason : entry.lattice.message}});
    }
    return list;
}

template <class I>
Json best_json(const BestLattice<I>& best, double total_seconds) {
    Json document;
    document["status"] = best.status == Outcome::proved ? "certified" : "undecided";
    document["message"] = best.message;
    long certified = 0, overlapping = 0;
    for (const SearchLattice<I>& lattice : best.checked) {
        certified += lattice.check.verdict == Outcome::proved;
        overlapping += lattice.check.verdict == Outcome::refuted;
    }
    document["candidates"] = {{"found", best.search.candidates.size()},
                              {"checked", best.checked.size()},
                              {"certified", certified},
                              {"overlapping", overlapping},
                              {"rejected", best.rejected},
                              {"rejected_means", "not denser in floating point than the best certified family, a repeat, "
                                                 "or beyond the first four checked"}};
    document["timing"] = {{"search_seconds", best.search.seconds}, {"total_seconds", total_seconds}};
    document["outside_domain"] = best.outside_domain;
    document["not_packings"] = not_packings_json(best);
    if (best.status != Outcome::proved) return document;
    document["admissible"] = true;
    document["phi"] = enclosure_json(best_phi(best));
    document["basis"] = basis_json(best_basis(best));
    document["configuration"] = configuration_text(best.configuration);
    if (best.source == BestSource::family) {
        const FamilyEntry<I>& entry = best.families[best.index];
        document["family"] = to_string(entry.lattice.family);
        document["contacts"] = {{"count", entry.check.contacts()}, {"vectors", triples_json(entry.check.contact_vectors)}};
    } else {
        const SearchLattice<I>& lattice = best.checked[best.index];
        document["family"] = nullptr;
        document["start"] = lattice.guess.start;
        // The scaled lattice clears every near-contact of the guess: no vector is at the contact
        // distance exactly.
        const std::string note =
            lattice.scale_exponent == 0
                ? "the certified basis is the guess snapped to small fractions"
                : "the certified basis is the guess scaled by 1 + 2^-" + std::to_string(lattice.scale_exponent) +
                      ", so its near-contacts clear the contact distance";
        document["contacts"] = {{"count", lattice.check.contacts()},
                                {"near_contacts_of_the_guess", triples_json(lattice.guess.near_contacts)},
                                {"note", note}};
    }
    document["beats"] = comparison_json(best);
    const LocalOptimum<I>& local = *best.local;
    document["locally_optimal"] = local.verdict == Outcome::proved ? Json(true) : Json(nullptr);
    document["locally_optimal_reason"] = local.reason;
    if (local.verdict == Outcome::proved) {
        Json multipliers = Json::array();
        for (const I& mu : local.multipliers) multipliers.push_back(enclosure_json(mu));
        document["critical_lattice"] = {{"phi", enclosure_json(*local.phi)}, {"basis", basis_json(*local.basis)},
                                        {"multipliers", multipliers}, {"rho", local.rho}};
    }
    return document;
}

// "yes" when the critical lattice at the best one is a certified strict local minimiser.
template <class I>
const char* locally_optimal_word(const BestLattice<I>& best) {
    return best.local->verdict == Outcome::proved ? "yes" : "not certified";
}

template <class I>
void print_table(const BestLattice<I>& best, int digits) {
    auto text = [digits](const I& x) {
        const DecimalEnclosure d = to_decimal(x, digits);
        return "[" + d.lo + ", " + d.hi + "]";
    };
    std::cout << "status       " << (best.status == Outcome::proved ? "certified" : "undecided") << "  (" << best.message << ")\n";
    if (best.status == Outcome::proved) {
        std::cout << "best         " << best_name(best) << "\n";
        std::cout << "phi          " << text(best_phi(best)) << "\n";
        std::cout << "configuration " << configuration_text(best.configuration) << "\n";
        std::cout << "locally optimal " << locally_optimal_word(best) << "  ("
                  << best.local->reason << ")\n";
        if (best.local->phi && best.local->verdict == Outcome::proved)
            std::cout << "critical phi " << text(*best.local->phi) << "\n";
        const Basis<I> basis = best_basis(best);
        for (int i = 0; i < 3; ++i)
            std::cout << "basis e" << i + 1 << "     " << text(basis[i][0]) << ", " << text(basis[i][1]) << ", " << text(basis[i][2]) << "\n";
        for (const FamilyComparison<I>& comparison : compare_families(best)) {
            const FamilyEntry<I>& entry = *comparison.entry;
            std::cout << "  vs " << to_string(entry.lattice.family) << "      phi " << text(*entry.lattice.phi) << "  gap "
                      << text(comparison.gap) << (comparison.relation == FamilyRelation::beats ? "  beats" : "  ties") << "\n";
        }
    }
    for (const FamilyEntry<I>& entry : best.families)
        if (entry.check.verdict != Outcome::proved)
            std::cout << "  " << to_string(entry.lattice.family) << "         not a certified packing here\n";
    std::cout << "candidates   " << best.search.candidates.size() << " found, " << best.checked.size() << " checked, "
              << best.rejected << " rejected\n";
}

void print_csv_header() {
    std::cout << "p,best,phi_lo,phi_hi,locally_optimal";
    for (Family family : convex_families_and_insertion())
        std::cout << "," << to_string(family) << "_lo," << to_string(family) << "_hi," << to_string(family) << "_packing";
    std::cout << "\n";
}

// One CSV row per p: the best lattice, whether locally optimal, and every family (phi, and
// whether it is a certified packing: yes, no (overlapping or no lattice), undecided, or outside
// its domain).
template <class I>
void print_csv_row(const Rational& p, const BestLattice<I>& best, int digits) {
    auto pair = [digits](const I& x) { return csv_enclosure(x, digits); };
    std::cout << decimal_or_fraction_text(p) << ",";
    if (best.status == Outcome::proved)
        std::cout << "\"" << best_name(best) << "\"," << pair(best_phi(best)) << ","
                  << locally_optimal_word(best);
    else
        std::cout << ",,,";
    for (Family family : convex_families_and_insertion()) {
        const FamilyEntry<I>* entry = family_entry(best, family);
        if (!entry) {
            std::cout << ",,,outside";
            continue;
        }
        const bool packing = entry->check.verdict == Outcome::proved;
        const bool no = entry->check.verdict == Outcome::refuted || entry->lattice.status == Outcome::refuted;
        std::cout << "," << (entry->lattice.phi ? pair(*entry->lattice.phi) : std::string(",")) << ","
                  << (packing ? "yes" : no ? "no" : "undecided");
    }
    std::cout << "\n";
}

// The scan as a table when it is not printed as CSV (--plot alone): the best lattice per p.
template <class I>
void print_table_row(const Rational& p, const BestLattice<I>& best, int digits) {
    std::string p_text = decimal_or_fraction_text(p);
    p_text.resize(std::max<std::size_t>(p_text.size(), 8), ' ');
    std::cout << p_text << " ";
    if (best.status != Outcome::proved) {
        std::cout << "undecided (" << best.message << ")\n";
        return;
    }
    const DecimalEnclosure phi = to_decimal(best_phi(best), digits);
    std::cout << "phi [" << phi.lo << ", " << phi.hi << "]  locally optimal "
              << locally_optimal_word(best) << "  " << best_name(best) << "\n";
}

// The curves of --plot: the best lattice's phi, and each family's, solid where the lattice
// check proves it a packing and dotted where it does not (phi = V/|det| is then no density).
// Midpoints: the enclosures are far narrower than a pixel.
template <class I>
struct ScanCurves {
    std::vector<PlotSeries> series;

    ScanCurves() {
        series.push_back({"densest certified lattice (superpack best)", Stroke::reference, 0, {}});
        int color = 0;
        for (Family family : convex_families_and_insertion()) {
            series.push_back({to_string(family), Stroke::solid, color, {}});
            series.push_back({std::string(to_string(family)) + ", not a certified packing", Stroke::dotted, color, {}});
            ++color;
        }
    }

    void add(const Rational& p, const BestLattice<I>& best) {
        const double x = p.get_d();
        series[0].points.push_back({x, best.status == Outcome::proved ? std::optional<double>(mid_double(best_phi(best))) : std::nullopt});
        std::size_t k = 1;
        for (Family family : convex_families_and_insertion()) {
            const FamilyEntry<I>* entry = family_entry(best, family);
            const bool packing = entry && entry->check.verdict == Outcome::proved;
            const std::optional<double> y =
                entry && entry->lattice.phi ? std::optional<double>(mid_double(*entry->lattice.phi)) : std::nullopt;
            series[k++].points.push_back({x, packing ? y : std::nullopt});
            series[k++].points.push_back({x, packing ? std::nullopt : y});
        }
    }
};

// Above 1/2 the densities lie in 0.7..1; below, the insertion's V(p) * 27/38 falls to 1e-5 at
// p = 1/10, so a scan that reaches below 1/2 gets a logarithmic axis from the decade below its
// least value. Both end at 1: a V/|det| above it (a dotted curve) is no density.
PlotAxes scan_axes(const std::vector<Rational>& values, const std::vector<PlotSeries>& series) {
    const std::string title = "Densest certified lattice packings of superballs (curves through the midpoints of the certified enclosures)";
    const bool concave = std::any_of(values.begin(), values.end(), [](const Rational& p) { return p < Rational(1, 2); });
    if (!concave) return {title, "p", "lattice packing density phi", std::make_pair(0.7, 1.0), false};
    double least = 1;
    for (const PlotSeries& curve : series)
        for (const PlotPoint& point : curve.points)
            if (point.y && *point.y > 0) least = std::min(least, *point.y);
    const double bottom = std::pow(10.0, std::floor(std::log10(least)));
    return {title, "p", "lattice packing density phi (log scale)", std::make_pair(bottom, 1.0), true};
}

int run_scan(const BestCommandOptions& options) {
    const std::vector<Rational> values = parse_scan(options.scan, max_scan_values);
    for (const Rational& p : values) require_best_domain(p);
    require_output_paths({{"--plot", options.plot}});
    if (!options.plot.empty()) require_plottable(options.plot);
    return with_field(options.digits, max_digits, [&](const auto& field, long digits) {
        using I = typename std::decay_t<decltype(field)>::Interval;
        const int print_digits = table_digits(digits, !options.digits.empty());
        if (options.csv) print_csv_header();
        BestOptions best_options;
        best_options.search.seed = options.seed;
        best_options.search.random_starts = options.starts;
        ScanCurves<I> curves;
        int code = exit_ok;
        std::size_t done = 0;
        for (const Rational& p : values) {
            std::cerr << "best scan: p = " << decimal_or_fraction_text(p) << " (" << ++done << "/" << values.size() << ")\n";
            const BestLattice<I> best =
                decided(within_contract([&] { return find_best_lattice(p, field, best_options); }), field, digits, max_digits);
            if (options.csv)
                print_csv_row(p, best, print_digits);
            else
                print_table_row(p, best, print_digits);
            curves.add(p, best);
            if (best.status != Outcome::proved) code = exit_undecided;
        }
        if (!options.plot.empty()) {
            plot_png(options.plot, scan_axes(values, curves.series), curves.series);
            std::cerr << "wrote " << options.plot << "\n";
        }
        if (code != exit_ok)
            throw Failure(code, std::string("best scan: undecided: some p has no certified lattice (") +
                                    (options.csv ? "empty CSV fields)" : "undecided rows)"));
        return code;
    });
}

// The options' checks: --p or --scan, and what goes with each, each with its usage error (a
// step of its own: run reads as check, then scan or certify one p).
void check_best_options(const BestCommandOptions& options) {
    if (!options.scan.empty()) {
        if (!options.p.empty()) throw Failure(exit_usage, "best: give one of --p and --scan, not both");
        if (!options.csv && options.plot.empty()) throw Failure(exit_usage, "best: --scan needs --csv or --plot FILE.png");
        if (options.json || !options.certificate.empty())
            throw Failure(exit_usage, "best: --scan prints CSV or a table, without --json or --certificate");
    } else if (options.csv) {
        throw Failure(exit_usage, "best: --csv needs --scan");
    } else if (!options.plot.empty()) {
        throw Failure(exit_usage, "best: --plot needs --scan a:b:h");
    } else if (options.p.empty()) {
        throw Failure(exit_usage, "best: give --p or --scan");
    }
    if (options.starts < 0 || options.starts > max_starts)
        throw InputError("--starts: 0 to " + std::to_string(max_starts) + " random starts, got " + std::to_string(options.starts));
}

int run(const BestCommandOptions& options) {
    check_best_options(options);
    if (!options.scan.empty()) return run_scan(options);
    const Rational p = parse_p(options.p);
    require_best_domain(p);
    if (!options.certificate.empty()) {
        require_output_paths({{"--certificate", options.certificate}});
        require_rounding_self_test();
    }
    return with_field(options.digits, max_digits, [&](const auto& field, long digits) {
        using I = typename std::decay_t<decltype(field)>::Interval;
        BestOptions best_options;
        best_options.search.seed = options.seed;
        best_options.search.random_starts = options.starts;
        std::cerr << "best: certifying the families and searching (" << options.starts << " random starts)\n";
        const auto start = std::chrono::steady_clock::now();
        const BestLattice<I> best =
            decided(within_contract([&] { return find_best_lattice(p, field, best_options); }), field, digits, max_digits);
        const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        Json document = header_json("best", field, digits);
        document["p"] = options.p;
        document["p_exact"] = rational_text(p);
        document["seed"] = options.seed;
        document.update(best_json(best, total));
        if (!options.certificate.empty() && best.status == Outcome::proved)
            write_certificate_or_fail(options.certificate, field, digits, max_digits, [&] {
                switch (best_certificate(best)) {
                    case BestCertificate::local_optimum: return local_optimum_certificate(*best.local, p, field, digits);
                    case BestCertificate::search_lattice:
                        return exact_lattice_certificate(best.checked[best.index].check, best.checked[best.index].basis, p, field, digits);
                    case BestCertificate::insertion_lattice:
                        return exact_lattice_certificate(best.families[best.index].check, minkowski_octahedron_basis(), p, field, digits);
                    case BestCertificate::family_lattice: break;
                }
                return family_certificate(best.families[best.index].lattice, p, field, digits);
            });
        if (options.json)
            print_json(document);
        else
            print_table(best, table_digits(digits, !options.digits.empty()));
        if (best.status != Outcome::proved) throw Failure(exit_undecided, "best: undecided: " + best.message);
        return exit_ok;
    });
}

void add_best(CLI::App& app) {
    auto options = std::make_shared<BestCommandOptions>();
    CLI::App* command = app.add_subcommand("best", "The densest lattice packing superpack certifies at p: families and a search");
    command->add_option("--p", options->p, "deformation parameter 1/10 <= p <= 10^6: a decimal or a fraction (below 1/2 a star body)");
    command->add_option("--scan", options->scan,
                        "a:b:h: one row per p = a, a + h, ... <= b (at most " + std::to_string(max_scan_values) +
                            "); needs --csv or --plot");
    command->add_flag("--csv", options->csv, "print the scan as CSV (else a table)");
    add_output_option(*command, "--plot", options->plot,
                      "with --scan: draw phi of the best lattice and of every family against p into this PNG (gnuplot)");
    add_digits_option(*command, options->digits, max_digits);
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    add_output_option(*command, "--certificate", options->certificate,
                      "write the certificate: local-optimum when the critical lattice is locally optimal, else the "
                      "best lattice's family-lattice, lattice-check or (below p = 1/2) star-lattice-check claim");
    add_seed_option(*command, options->seed, "seed of the search's random starts and directions (default 1)");
    command->add_option("--starts", options->starts,
                        "random starts besides the families, 0 to " + std::to_string(max_starts) + " (default 16)");
    command->callback([options] { run(*options); });
}

const SubcommandRegistration registration("best", add_best);

}  // namespace

}  // namespace superpack::cli
