// superpack crossover cubic|octahedral [--digits D] [--json] [--certificate FILE]
#include <chrono>
#include <memory>

#include "common.hpp"
#include "output_paths.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/cert/crossover_certificate.hpp"
#include "superpack/problems/crossover/crossover_json.hpp"

namespace superpack::cli {

namespace {

struct CrossoverOptions {
    std::string kind, digits, certificate;
    bool json = false;
};

template <class I>
void row(const std::string& name, const std::optional<I>& x, int digits) {
    if (!x) {
        std::cout << "  " << name << ": not certified\n";
        return;
    }
    const DecimalEnclosure text = to_decimal(*x, digits);
    std::cout << "  " << name << std::string(name.size() < 14 ? 14 - name.size() : 1, ' ') << "[" << text.lo << ", "
              << text.hi << "]  width " << width_text(*x) << "\n";
}

// Measured (README): 300 digits take under a second. Beyond, the refinement's target width
// 10^-D (a binary64 number) underflows and the digits asked for would not be delivered.
constexpr long max_digits = 300;

template <class I>
void print_cubic(const CubicCrossover<I>& crossover, int digits) {
    std::cout << "cubic crossover: phi_C0(p) = phi_C1(p), g = phi_C1 - phi_C0 on [1, 10]\n";
    row("p*_c", crossover.p, digits);
    row("phi*_c", crossover.phi, digits);
    std::size_t counts[4] = {0, 0, 0, 0};
    for (const auto& piece : crossover.pieces) ++counts[static_cast<int>(piece.claim)];
    std::cout << "  pieces of [1, 10]: " << crossover.pieces.size() << " (negative " << counts[0] << ", positive "
              << counts[1] << ", root " << counts[2] << ", undecided " << counts[3] << ")\n";
    if (crossover.certified)
        std::cout << "  proved: g < 0 on (1, p*_c) (C0 denser), g > 0 on (p*_c, 10] (C1 denser); p*_c is the only "
                     "zero of g in (1, 10]\n";
    else
        std::cout << "  not certified: " << crossover.message << "\n";
}

template <class I>
void print_octahedral(const OctahedralCrossover<I>& crossover, int digits) {
    std::cout << "octahedral crossover: Eq. (6) 2 (1 - 2^(1-2p))^(1/(2p)) = 1 on (1/2, 1]\n";
    if (crossover.newton) {
        const std::optional<I> root = crossover.newton->box;
        row("root of (6)", root, digits);
    }
    row("ln3/ln4", crossover.ln3_over_ln4, digits);
    std::cout << "  root of Eq. (6) overlaps ln3/ln4: " << agreement_word(crossover.closed_form) << "\n";
    row("phi_O0", crossover.o0.phi, digits);
    row("phi_O1", crossover.o1_phi, digits);
    std::cout << "  O0 and O1 (q = 0, s = 1) densities meet: " << agreement_word(crossover.densities_meet)
              << "; same lattice (B_O0 = U B_O1): " << (crossover.same_lattice ? "yes" : "not shown") << "\n";
    if (!crossover.certified) std::cout << "  not certified: " << crossover.message << "\n";
}

int run(const CrossoverOptions& options) {
    if (options.kind != "cubic" && options.kind != "octahedral")
        throw Failure(exit_usage, "crossover: expected 'cubic' or 'octahedral', got '" + options.kind + "'");
    if (!options.certificate.empty()) {
        require_output_paths({{"--certificate", options.certificate}});
        require_rounding_self_test();
    }
    return with_field(options.digits, max_digits, [&](const auto& field, long digits) {
        const int print_digits = table_digits(digits, !options.digits.empty());
        const auto start = std::chrono::steady_clock::now();
        Json document = header_json("crossover", field, digits);
        bool certified = false;
        std::string message;
        Json certificate;  // built only for a certified result
        if (options.kind == "cubic") {
            std::cerr << "crossover: proving the sign of phi_C1 - phi_C0 on [1, 10]...\n";
            const auto crossover = decided(within_contract([&] { return certify_cubic_crossover(field, digits); }), field, digits, max_digits);
            document.update(cubic_crossover_json(crossover));
            if (!options.json) print_cubic(crossover, print_digits);
            certified = crossover.certified;
            message = crossover.message;
            if (certified && !options.certificate.empty())
                certificate = decided(within_contract([&] { return cubic_crossover_certificate(crossover, field, digits); }), field, digits, max_digits);
        } else {
            const auto crossover =
                decided(within_contract([&] { return certify_octahedral_crossover(field, digits); }), field, digits, max_digits);
            document.update(octahedral_crossover_json(crossover));
            if (!options.json) print_octahedral(crossover, print_digits);
            certified = crossover.certified;
            message = crossover.message;
            if (certified && !options.certificate.empty())
                certificate =
                    decided(within_contract([&] { return octahedral_crossover_certificate(crossover, field, digits); }), field, digits, max_digits);
        }
        if (!certificate.is_null())
            write_certificate_or_fail(options.certificate, field, digits, max_digits, [&] { return certificate; });
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        document["seconds"] = seconds;
        if (options.json) print_json(document);
        if (!certified) throw Failure(exit_undecided, "crossover " + options.kind + ": undecided: " + message);
        return exit_ok;
    });
}

}  // namespace

void add_crossover(CLI::App& app) {
    auto options = std::make_shared<CrossoverOptions>();
    CLI::App* command = app.add_subcommand(
        "crossover", "Certified crossover p*_c (C0 = C1, unique on [1, 10]) or p*_o (Eq. 6, O0 meets O1)");
    command->add_option("kind", options->kind, "cubic or octahedral")->required();
    add_digits_option(*command, options->digits, max_digits);
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    add_output_option(*command, "--certificate", options->certificate,
                      "write a certificate of the crossover (replay it with `superpack verify FILE`); nothing when undecided");
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("crossover", add_crossover);
}  // namespace

}  // namespace superpack::cli
