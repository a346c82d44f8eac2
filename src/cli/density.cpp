// superpack density --family F --p P [--digits D] [--json] [--certificate FILE]
#include <memory>

#include "common.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/cert/family_certificate.hpp"

namespace superpack::cli {

namespace {

struct DensityOptions {
    std::string family, p, digits, certificate;
    bool json = false;
};

template <class I>
void print_table(const FamilyLattice<I>& lattice, const std::string& p, const char* backend) {
    std::cout << "family " << to_string(lattice.family) << " at p = " << p << "  (" << backend << ")\n";
    auto row = [](const std::string& name, const I& x) {
        const DecimalEnclosure text = to_decimal(x, 20);
        std::cout << "  " << name << std::string(name.size() < 12 ? 12 - name.size() : 1, ' ') << "[" << text.lo
                  << ", " << text.hi << "]  width " << width_text(x) << "\n";
    };
    if (lattice.volume) row("volume", *lattice.volume);
    for (const auto& parameter : lattice.parameters) row(parameter.name, parameter.value);
    if (lattice.phi) {
        row("|det|", abs(*lattice.determinant));
        row("phi", *lattice.phi);
    }
    std::cout << "  roots of the contact equations certified: " << lattice.branches.size() << "\n";
    if (!lattice.message.empty()) std::cout << "  note: " << lattice.message << "\n";
}

int run(const DensityOptions& options) {
    const Family family = parse_family(options.family);
    const Rational p = parse_p(options.p);
    if (!options.certificate.empty()) require_rounding_self_test();
    return with_field(options.digits, [&](const auto& field, long digits) {
        const auto lattice = enclose_family(family, p, field);
        if (options.json) {
            Json document = header_json("density", field, digits);
            document["family"] = to_string(family);
            document["p"] = options.p;
            document["p_exact"] = rational_text(p);
            document.update(family_json(lattice));
            std::cout << document.dump(2) << "\n";
        } else {
            print_table(lattice, options.p, field.backend());
        }
        if (!options.certificate.empty() && lattice.status == FamilyStatus::certified) {
            const Json certificate = family_certificate(lattice, p, field, digits);
            try {
                write_certificate(options.certificate, certificate);
            } catch (const std::runtime_error& error) {
                throw Failure(exit_usage, std::string("error: no certificate written: ") + error.what());
            }
        }
        if (lattice.status == FamilyStatus::no_lattice)
            throw Failure(exit_impossible, std::string(to_string(family)) + ": " + lattice.message);
        if (lattice.status == FamilyStatus::undecided)
            throw Failure(exit_undecided, std::string(to_string(family)) + ": undecided: " + lattice.message);
        return exit_ok;
    });
}

}  // namespace

void add_density(CLI::App& app) {
    auto options = std::make_shared<DensityOptions>();
    CLI::App* command = app.add_subcommand("density", "Certified density of one lattice family at one p");
    command->add_option("--family", options->family, "C0, C1 (p >= 1), O0 (1/2 < p <= 1) or O1 (p >= 1/2)")->required();
    command->add_option("--p", options->p, "deformation parameter: a decimal (1.15) or a fraction (23/20)")->required();
    command->add_option("--digits", options->digits, "significant digits (Arb balls); default: binary64 intervals");
    command->add_option("--certificate", options->certificate,
                        "write a certificate of the density (replay it with `superpack verify FILE`)");
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("density", add_density);

}  // namespace

}  // namespace superpack::cli
