// superpack report: the main job (`make demo`). Every family at the paper's sample values of
// p, which one is densest at each p, and a JSON log written atomically under out/.
#include <iomanip>
#include <memory>

#include "common.hpp"
#include "superpack/cert/atomic_file.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/problems/family_lattice_check.hpp"

namespace superpack::cli {

namespace {

struct ReportOptions {
    std::string digits, output = "out/report.json", p_values = "0.55,0.6,0.7,0.8,0.9,1,1.1,1.5,2,3,5";
    bool json = false;
};

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    for (char c : text) {
        if (c == separator) {
            parts.push_back(part);
            part.clear();
        } else {
            part += c;
        }
    }
    parts.push_back(part);
    return parts;
}

// Among the lattices certified to be packings: the family whose phi is certainly above every
// other's, or those that cannot be separated from the best (joined by '='), or "none".
template <class I>
std::string densest(const std::vector<FamilyLattice<I>>& lattices, const std::vector<Verdict>& verdicts) {
    std::vector<const FamilyLattice<I>*> certified;
    for (std::size_t k = 0; k < lattices.size(); ++k)
        if (lattices[k].phi && verdicts[k] == Verdict::admissible) certified.push_back(&lattices[k]);
    if (certified.empty()) return "none";
    const FamilyLattice<I>* leader = certified.front();
    for (const auto* lattice : certified)
        if (mid_double(*lattice->phi) > mid_double(*leader->phi)) leader = lattice;
    std::string names = to_string(leader->family);
    bool alone = true;
    for (const auto* lattice : certified)
        if (lattice != leader && !certainly_less(*lattice->phi, *leader->phi)) {
            names += std::string("=") + to_string(lattice->family);
            alone = false;
        }
    return alone ? names : names + " (not separated)";
}

int run(const ReportOptions& options) {
    return with_field(options.digits, [&](const auto& field, long digits) {
        using I = typename std::decay_t<decltype(field)>::Interval;
        Json document = header_json("report", field, digits);
        Json rows = Json::array();
        if (!options.json) {
            std::cout << "Certified densities phi = V_sb / |det| of the JST 2009 lattice families (" << field.backend() << ")\n";
            std::cout << std::left << std::setw(6) << "p";
            for (Family family : all_families()) std::cout << std::setw(31) << to_string(family);
            std::cout << "densest\n";
        }
        const auto values = split(options.p_values, ',');
        for (std::size_t index = 0; index < values.size(); ++index) {
            const Rational p = parse_p(values[index]);
            std::cerr << "report: p = " << values[index] << " (" << index + 1 << "/" << values.size() << ")\n";
            std::vector<FamilyLattice<I>> lattices;
            std::vector<Verdict> verdicts;
            Json row{{"p", values[index]}, {"families", Json::object()}};
            if (!options.json) std::cout << std::setw(6) << values[index];
            for (Family family : all_families()) {
                std::string cell = "-  (outside domain)";
                try {
                    lattices.push_back(enclose_family(family, p, field));
                    const auto& lattice = lattices.back();
                    const LatticeCheck<I> check = check_family_lattice(lattice, field.rational(p));
                    verdicts.push_back(check.verdict);
                    Json family_row = family_json(lattice);
                    family_row["packing"] = lattice_check_json(check, false);
                    row["families"][to_string(family)] = family_row;
                    if (lattice.phi) {
                        const DecimalEnclosure text = to_fixed(*lattice.phi, 10);
                        const char* mark = check.verdict == Verdict::admissible ? " " : check.verdict == Verdict::overlapping ? "x" : "?";
                        cell = "[" + text.lo + ", " + text.hi + "]" + mark;
                    } else {
                        cell = lattice.status == FamilyStatus::no_lattice ? "-  (no lattice)" : "?  (undecided)";
                    }
                } catch (const InputError&) {
                    row["families"][to_string(family)] = Json{{"status", "outside_domain"},
                                                              {"domain", family_domain_text(family)}};
                }
                if (!options.json) std::cout << std::setw(31) << cell;
            }
            row["densest"] = densest(lattices, verdicts);
            if (!options.json) std::cout << row["densest"].template get<std::string>() << "\n";
            rows.push_back(row);
        }
        document["rows"] = rows;
        const std::string text = document.dump(2) + "\n";
        write_atomically(options.output, text);
        if (options.json)
            std::cout << text;
        else
            std::cout << "phi enclosures [lo, hi] to 10 decimals, lo rounded down and hi up. After the\n"
                      << "enclosure: ' ' a certified packing, 'x' certified to overlap (not a packing: its phi is\n"
                      << "no packing density), '?' undecided. 'densest' ranks certified packings only.\n"
                      << "full enclosures and root proofs: " << options.output << "\n";
        return exit_ok;
    });
}

}  // namespace

void add_report(CLI::App& app) {
    auto options = std::make_shared<ReportOptions>();
    CLI::App* command = app.add_subcommand("report", "Every family at the paper's sample p, and the densest");
    command->add_option("--digits", options->digits, "significant digits (Arb balls); default: binary64 intervals");
    command->add_option("--p-values", options->p_values, "comma-separated p values")->capture_default_str();
    command->add_option("--output", options->output, "JSON log, written atomically")->capture_default_str();
    command->add_flag("--json", options->json, "print the JSON log on stdout instead of the table");
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("report", add_report);

}  // namespace

}  // namespace superpack::cli
