// superpack density --family F --p P [--digits D] [--json] [--certificate FILE]
// The family's certified lattice, phi = V / |det|, and whether the lattice is a packing: phi is
// called a density only when it is.
#include <memory>

#include "common.hpp"
#include "output_paths.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/cert/family_certificate.hpp"
#include "superpack/problems/families/family_lattice_check.hpp"

namespace superpack::cli {

namespace {

struct DensityOptions {
    std::string family, p, digits, certificate;
    bool json = false;
};

// Measured (README): at 10000 digits O1 at p = 0.6 takes about 67 s of one core (C0 at p = 1.5
// 0.4 s; C0 at 100000 digits 70 s).
constexpr long max_digits = 10000;

const char* const not_a_packing = "not a packing: phi is V/|det|, no density";

template <class I>
void print_table(const FamilyLattice<I>& lattice, const std::optional<LatticeCheck<I>>& check, const std::string& p,
                 const char* backend, int digits) {
    std::cout << "family " << to_string(lattice.family) << " at p = " << p << "  (" << backend << ")\n";
    std::cout << "  source      " << family_source(lattice.family) << "\n";
    auto text = [digits](const I& x) {
        const DecimalEnclosure decimal = to_decimal(x, digits);
        return "[" + decimal.lo + ", " + decimal.hi + "]";
    };
    auto row = [&](const std::string& name, const I& x) {
        std::cout << "  " << name << std::string(name.size() < 12 ? 12 - name.size() : 1, ' ') << text(x) << "  width "
                  << width_text(x) << "\n";
    };
    if (lattice.volume) row("volume", *lattice.volume);
    for (const auto& parameter : lattice.parameters) row(parameter.name, parameter.value);
    if (lattice.basis)
        for (std::size_t k = 0; k < 3; ++k)
            std::cout << "  e" << k + 1 << "          (" << text((*lattice.basis)[k][0]) << ", " << text((*lattice.basis)[k][1])
                      << ", " << text((*lattice.basis)[k][2]) << ")\n";
    if (lattice.phi) {
        row("|det|", abs(*lattice.determinant));
        row("phi", *lattice.phi);
    }
    std::cout << "  roots of the contact equations certified: " << lattice.branches.size() << "\n";
    if (check) {
        std::cout << "  packing     ";
        switch (check->verdict) {
            case Outcome::proved:
                std::cout << "yes, " << check->contacts() << " contacts: phi is its packing density\n";
                break;
            case Outcome::refuted:
                std::cout << "no: " << not_a_packing;
                if (check->witness) {
                    const auto& c = check->witness->coefficients;
                    std::cout << " (witness (" << c[0] << ", " << c[1] << ", " << c[2] << "), norm " << text(check->witness->norm)
                              << " < 2)";
                }
                std::cout << "\n";
                break;
            case Outcome::undecided: std::cout << "undecided: " << check->reason << "\n"; break;
        }
    }
    if (!lattice.message.empty()) std::cout << "  note: " << lattice.message << "\n";
}

int run(const DensityOptions& options) {
    const Family family = parse_family(options.family);
    const Rational p = parse_p(options.p);
    require_in_domain(family, p);
    if (!options.certificate.empty()) {
        require_certificate_kind(p, family);
        require_output_paths({{"--certificate", options.certificate}});
        require_rounding_self_test();
    }
    return with_field(options.digits, max_digits, [&](const auto& field, long digits) {
        using I = typename std::decay_t<decltype(field)>::Interval;
        const auto lattice = decided(within_contract([&] { return enclose_family(family, p, field); }), field, digits, max_digits);
        std::optional<LatticeCheck<I>> check;
        if (lattice.status == Outcome::proved)
            check = decided(within_contract([&] { return check_family_lattice(lattice, p); }), field, digits, max_digits);
        if (!options.certificate.empty() && lattice.status == Outcome::proved) {
            const Json certificate =
                decided(within_contract([&] { return family_certificate(lattice, p, field, digits); }), field, digits, max_digits);
            write_certificate_or_fail(options.certificate, field, digits, max_digits, [&] { return certificate; });
        }
        if (options.json) {
            Json document = header_json("density", field, digits);
            document["family"] = to_string(family);
            document["p"] = options.p;
            document["p_exact"] = rational_text(p);
            document["source"] = family_source(family);
            document.update(family_json(lattice));
            document["packing"] = check ? lattice_check_json(*check, false) : Json(nullptr);
            if (check && check->verdict == Outcome::refuted) document["note"] = not_a_packing;
            print_json(document);
        } else {
            print_table(lattice, check, options.p, field.backend(), table_digits(digits, !options.digits.empty()));
        }
        if (lattice.status == Outcome::refuted)
            throw Failure(exit_impossible, std::string(to_string(family)) + ": " + lattice.message);
        if (lattice.status == Outcome::undecided)
            throw Failure(exit_undecided, std::string(to_string(family)) + ": undecided: " + lattice.message);
        if (check->verdict == Outcome::undecided)
            throw Failure(exit_undecided, std::string(to_string(family)) + ": packing undecided: " + check->reason);
        return exit_ok;
    });
}

}  // namespace

void add_density(CLI::App& app) {
    auto options = std::make_shared<DensityOptions>();
    CLI::App* command = app.add_subcommand("density", "Certified density of one lattice family at one p");
    command->add_option("--family", options->family, "C0, C1 (p >= 1), O0 (1/2 < p <= 1), O1 (p >= 1/2), D14 (1/2 <= p <= 1), S6 (ln3/ln4 < p < 1) or minkowski-insertion (0 < p <= 1/2)")->required();
    command->add_option("--p", options->p, std::string("deformation parameter: a decimal (1.15) or a fraction (23/20); ") + supported_p_text)->required();
    add_digits_option(*command, options->digits, max_digits);
    add_output_option(*command, "--certificate", options->certificate,
                      "write a certificate of the density (replay it with `superpack verify FILE`)");
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("density", add_density);

}  // namespace

}  // namespace superpack::cli
