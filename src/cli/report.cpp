// superpack report: the main job (`make demo`). Every family at the paper's sample values of
// p, which one is densest at each p, and a JSON log written atomically under out/.
#include <iomanip>
#include <memory>

#include "common.hpp"
#include "output_paths.hpp"
#include "superpack/cert/atomic_file.hpp"
#include "superpack/arith/contract.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/problems/families/densest_family.hpp"
#include "superpack/problems/families/family_lattice_check.hpp"
#include "superpack/problems/families/family_registry.hpp"

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

// Measured (README): the whole report at 1000 digits takes about 16 s.
constexpr long max_digits = 1000;
constexpr std::size_t max_p_values = 100;

struct Cell {
    std::string text;
    bool undecided = false;
};

// One family at one p: the table cell, and its entry in the JSON log.
template <class Field, class I = typename Field::Interval>
Cell family_cell(Family family, const Rational& p, const Field& field, int decimals, Json& entry,
                 std::vector<FamilyLattice<I>>& lattices, std::vector<Outcome>& verdicts) {
    if (!family_domain(family, p).inside()) {
        entry = Json{{"status", "outside_domain"}, {"domain", family_domain_text(family)}};
        return {"-  (outside domain)"};
    }
    const Contracted<Cell> cell = within_contract([&] {
        FamilyLattice<I> lattice = enclose_family(family, p, field);
        const LatticeCheck<I> check = check_family_lattice(lattice, field.rational(p));
        entry = family_json(lattice);
        entry["packing"] = lattice_check_json(check, false);
        Cell decided;
        if (lattice.phi) {
            const DecimalEnclosure text = to_fixed(*lattice.phi, decimals);
            const char* mark = check.verdict == Outcome::proved ? " " : check.verdict == Outcome::refuted ? "x" : "?";
            decided = {"[" + text.lo + ", " + text.hi + "]" + mark, check.verdict == Outcome::undecided};
        } else if (lattice.status == Outcome::refuted) {
            decided = {"-  (no lattice)"};
        } else {
            decided = {"?  (undecided)", true};
        }
        lattices.push_back(std::move(lattice));
        verdicts.push_back(check.verdict);
        return decided;
    });
    if (cell.status == ContractStatus::held) return *cell.value;
    // A contract refusal at this precision leaves this cell undecided, not the report.
    entry = Json{{"status", "undecided"},
                 {"message", "undecided at this precision (" + cell.refusal + ": an enclosure is too wide for the function's contract)"}};
    return {"?  (undecided)", true};
}

int run(const ReportOptions& options, bool default_output) {
    const auto values = split(options.p_values, ',');
    if (values.size() > max_p_values)
        throw InputError("--p-values: at most " + std::to_string(max_p_values) + " values, got " + std::to_string(values.size()));
    std::vector<Rational> ps;
    for (const std::string& value : values) ps.push_back(parse_p(value, "--p-values"));
    if (default_output) create_default_directory("out");
    require_output_paths({{"--output", options.output}});
    return with_field(options.digits, max_digits, [&](const auto& field, long digits) {
        using I = typename std::decay_t<decltype(field)>::Interval;
        const int decimals = options.digits.empty() ? 10 : static_cast<int>(digits);
        Json document = header_json("report", field, digits);
        Json rows = Json::array();
        std::vector<std::vector<std::string>> table;
        std::size_t undecided = 0;
        for (std::size_t index = 0; index < values.size(); ++index) {
            const Rational& p = ps[index];
            std::cerr << "report: p = " << values[index] << " (" << index + 1 << "/" << values.size() << ")\n";
            std::vector<FamilyLattice<I>> lattices;
            std::vector<Outcome> verdicts;
            Json row{{"p", values[index]}, {"families", Json::object()}};
            std::vector<std::string> line{values[index]};
            for (Family family : all_families()) {
                Json entry;
                const Cell cell = family_cell(family, p, field, decimals, entry, lattices, verdicts);
                row["families"][to_string(family)] = entry;
                line.push_back(cell.text);
                if (cell.undecided) ++undecided;
            }
            row["densest"] = densest_family(lattices, verdicts);
            line.push_back(row["densest"].template get<std::string>());
            rows.push_back(row);
            table.push_back(line);
        }
        document["rows"] = rows;
        document["undecided_cells"] = undecided;
        write_atomically(options.output, document.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
        if (options.json) {
            print_json(document);
        } else {
            std::vector<std::string> heading{"p"};
            for (Family family : all_families()) heading.push_back(to_string(family));
            heading.push_back("densest");
            // Every column as wide as its widest entry: long p such as 0.5000000000000000001 stay aligned.
            std::vector<std::size_t> widths(heading.size());
            for (std::size_t k = 0; k < heading.size(); ++k) widths[k] = heading[k].size();
            for (const auto& line : table)
                for (std::size_t k = 0; k < line.size(); ++k) widths[k] = std::max(widths[k], line[k].size());
            auto print_line = [&](const std::vector<std::string>& line) {
                for (std::size_t k = 0; k + 1 < line.size(); ++k) std::cout << std::left << std::setw(widths[k] + 2) << line[k];
                std::cout << line.back() << "\n";
            };
            std::cout << "Certified phi = V_sb / |det| of the lattice families (C0, C1, O0, O1: JST 2009; D14: Dostert & "
                         "Vallentin 2020; S6: superpack's six-pair family, NOTES.md 4.2) ("
                      << field.backend() << ")\n";
            print_line(heading);
            for (const auto& line : table) print_line(line);
            std::cout << "phi enclosures [lo, hi] to " << decimals << " decimals, lo rounded down and hi up. After the\n"
                      << "enclosure: ' ' a certified packing (phi is its density), 'x' certified to overlap (not a\n"
                      << "packing: its phi is no packing density), '?' undecided. 'densest' ranks these families' certified\n"
                      << "packings only; `superpack best --p P` also searches all lattices (on p*_o < p < 1 it finds S6,\n"
                      << "0.24% denser than O0 at p = 0.9, NOTES.md section 9).\n"
                      << "full enclosures and root proofs: " << options.output << "\n";
        }
        if (undecided > 0)
            throw Failure(exit_undecided, "report: undecided: " + std::to_string(undecided) + " cell(s) marked '?' (reasons in " +
                                              options.output + ")");
        return exit_ok;
    });
}

}  // namespace

void add_report(CLI::App& app) {
    auto options = std::make_shared<ReportOptions>();
    CLI::App* command = app.add_subcommand("report", "Every family at the paper's sample p, and the densest");
    add_digits_option(*command, options->digits, max_digits);
    command->add_option("--p-values", options->p_values, "comma-separated p values (at most " + std::to_string(max_p_values) + "; " + supported_p_text + ")")
        ->capture_default_str();
    CLI::Option* output = add_output_option(*command, "--output", options->output,
                                            "JSON log, written atomically (its directory must exist; the default out/ "
                                            "is created)")
                              ->capture_default_str();
    command->add_flag("--json", options->json, "print the JSON log on stdout instead of the table");
    command->callback([options, output] { run(*options, output->count() == 0); });
}

namespace {
const SubcommandRegistration registration("report", add_report);

}  // namespace

}  // namespace superpack::cli
