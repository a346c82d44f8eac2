// superpack check-lattice --p P (--basis "a,b,c; d,e,f; g,h,i" | --family F) [--digits D] [--json]
//                         [--certificate FILE]
#include <memory>

#include "common.hpp"
#include "output_paths.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/cert/audit_certificate.hpp"
#include "superpack/cert/family_certificate.hpp"
#include "superpack/cert/star_lattice_certificate.hpp"
#include "superpack/problems/families/family_lattice_check.hpp"
#include "superpack/problems/families/family_registry.hpp"

namespace superpack::cli {

namespace {

struct CheckLatticeOptions {
    std::string p, basis, family, digits, certificate;
    bool json = false;
};

std::string triple_text(const Coefficients& c) {
    return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ")";
}

// Measured (README): the family O1 at p = 0.6 and its check take about 19 s at 5000 digits.
constexpr long max_digits = 5000;

template <class I>
void print_table(const LatticeCheck<I>& check, const std::optional<I>& phi, int digits) {
    auto enclosure_text = [digits](const I& x) {
        const DecimalEnclosure text = to_decimal(x, digits);
        return "[" + text.lo + ", " + text.hi + "]";
    };
    std::cout << "verdict      " << packing_word(check.verdict) << "  (" << check.reason << ")\n";
    if (check.min_norm) std::cout << "min norm     " << enclosure_text(*check.min_norm) << "\n";
    std::cout << "contacts     " << check.contacts() << "\n";
    for (const auto& c : check.contact_vectors) std::cout << "  contact    " << triple_text(c) << "\n";
    for (const auto& x : check.near_contacts)
        std::cout << "  near       " << triple_text(x.coefficients) << "  norm " << enclosure_text(x.norm) << "\n";
    if (check.witness)
        std::cout << "witness      " << triple_text(check.witness->coefficients) << "  norm "
                  << enclosure_text(check.witness->norm) << "\n";
    if (check.witness_point) {
        const auto& w = *check.witness_point;
        std::cout << "  point      x = (" << enclosure_text(w.point[0]) << ", " << enclosure_text(w.point[1]) << ", "
                  << enclosure_text(w.point[2]) << ")\n"
                  << "             g(x) " << enclosure_text(w.value) << ", g(x - v) " << enclosure_text(w.value_at_translate)
                  << "  (both < 1: x is inside K and K + v)\n";
    }
    // V / |det| is a packing density only where the packing is proved.
    if (phi && check.verdict == Outcome::proved) std::cout << "phi          " << enclosure_text(*phi) << "\n";
    if (phi && check.verdict != Outcome::proved)
        std::cout << "V/|det|      " << enclosure_text(*phi) << "  (not a packing density: no packing proved)\n";
    if (check.reduction) {
        const Transform& u = check.reduction->transform;
        std::cout << "coefficients of contacts and witness are in the given basis; enumerated in its LLL reduction\n"
                  << "reduced      r_i = sum_k U_ik e_k, U = " << triple_text(u[0]) << ", " << triple_text(u[1]) << ", "
                  << triple_text(u[2]) << "\n";
    }
    std::cout << "enumerated   |a| <= " << check.coefficient_bound[0] << ", |b| <= " << check.coefficient_bound[1]
              << ", |c| <= " << check.coefficient_bound[2] << (check.reduction ? "  (in the reduced basis)" : "") << "\n";
}

int run(const CheckLatticeOptions& options) {
    if (options.basis.empty() == options.family.empty())
        throw Failure(exit_usage, "check-lattice: give exactly one of --basis and --family");
    const Rational p = parse_p(options.p);
    if (options.basis.size() > 1000) throw InputError("--basis: at most 1000 characters, got " + std::to_string(options.basis.size()));
    if (!options.certificate.empty()) {
        // A family whose basis is exact (the insertion's, Minkowski's) has its check certified as a basis.
        const std::optional<Family> family = options.family.empty() ? std::nullopt : std::optional<Family>(parse_family(options.family));
        if (family && family_definition(*family).exact_basis)
            require_in_domain(*family, p);
        else
            require_certificate_kind(p, family);
        require_output_paths({{"--certificate", options.certificate}});
        require_rounding_self_test();
    }
    return with_field(options.digits, max_digits, [&](const auto& field, long digits) {
        using I = typename std::decay_t<decltype(field)>::Interval;
        LatticeCheck<I> check;
        std::optional<I> phi;
        Json document = header_json("check-lattice", field, digits);
        document["p"] = options.p;
        document["p_exact"] = rational_text(p);
        if (!options.family.empty()) {
            const Family family = parse_family(options.family);
            const auto lattice = decided(within_contract([&] { return enclose_family(family, p, field); }), field, digits, max_digits);
            check = decided(within_contract([&] { return check_family_lattice(lattice, p); }), field, digits, max_digits);
            phi = lattice.phi;
            document["family"] = to_string(family);
            if (!options.certificate.empty() && check.verdict != Outcome::undecided)
                write_certificate_or_fail(options.certificate, field, digits, max_digits, [&] {
                    const auto exact_basis = family_definition(family).exact_basis;
                    return exact_basis ? exact_lattice_certificate(check, exact_basis(), p, field, digits)
                                       : family_lattice_check_certificate(lattice, check, p, field, digits);
                });
        } else {
            const Basis<Rational> basis = parse_basis(options.basis);
            check = decided(within_contract([&] { return check_exact_lattice(basis, p, field); }), field, digits, max_digits);
            phi = decided(within_contract([&] { return enclose_ball_volume(field.rational(p), 3) / abs(determinant(enclose_basis(basis, field))); }),
                          field, digits, max_digits);
            document["basis"] = options.basis;
            if (!options.certificate.empty() && check.verdict != Outcome::undecided)
                write_certificate_or_fail(options.certificate, field, digits, max_digits,
                                          [&] { return exact_lattice_certificate(check, basis, p, field, digits); });
        }
        if (options.json) {
            document.update(lattice_check_json(check, false));
            document["phi"] = phi ? enclosure_json(*phi) : Json(nullptr);
            print_json(document);
        } else {
            print_table(check, phi, table_digits(digits, !options.digits.empty()));
        }
        // Overlap with a witness is a certified answer, like a packing: exit 0 for both.
        if (check.verdict == Outcome::undecided) throw Failure(exit_undecided, "check-lattice: undecided: " + check.reason);
        return exit_ok;
    });
}

}  // namespace

void add_check_lattice(CLI::App& app) {
    auto options = std::make_shared<CheckLatticeOptions>();
    CLI::App* command = app.add_subcommand("check-lattice", "Certify that a lattice is a superball packing (or find an overlap)");
    command->add_option("--p", options->p, std::string("deformation parameter p > 0 (below 1/2 with --basis only: the star-body overlap test): a decimal or a fraction (") + supported_p_text + ")")->required();
    command->add_option("--basis", options->basis, "exact basis rows \"a,b,c; d,e,f; g,h,i\" (decimals or fractions)");
    command->add_option("--family", options->family, "C0, C1, O0, O1, D14, S6 or minkowski-insertion (its certified enclosures)");
    add_digits_option(*command, options->digits, max_digits);
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    add_output_option(*command, "--certificate", options->certificate,
                      "write a certificate of the verdict (replay it with `superpack verify FILE`); nothing when undecided");
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("check-lattice", add_check_lattice);
}  // namespace

}  // namespace superpack::cli
