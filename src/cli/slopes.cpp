// superpack slopes [--digits D] [--json] [--certificate FILE]
#include <memory>

#include "common.hpp"
#include "output_paths.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/cert/crossover_certificate.hpp"
#include "superpack/problems/crossover/crossover_json.hpp"

namespace superpack::cli {

namespace {

struct SlopesOptions {
    std::string digits, certificate;
    bool json = false;
};

// Measured (README): the slopes at 10000 digits take about 2 s.
constexpr long max_digits = 10000;

template <class I>
void row(const std::string& name, const std::optional<I>& x, int digits) {
    if (!x) {
        std::cout << "  " << name << ": not certified\n";
        return;
    }
    const DecimalEnclosure text = to_decimal(*x, digits);
    std::cout << "  " << name << std::string(name.size() < 22 ? 22 - name.size() : 1, ' ') << "[" << text.lo << ", "
              << text.hi << "]  width " << width_text(*x) << "\n";
}

template <class I>
void print_table(const SphereSlopes<I>& slopes, int digits) {
    std::cout << "slopes of the family densities at p = 1\n";
    row("C0 dphi/dp (p -> 1+)", slopes.c0.slope, digits);
    row("C1 dphi/dp (p -> 1+)", slopes.c1.slope, digits);
    row("O0 dphi/dp (p -> 1-)", slopes.o0.slope, digits);
    row("a_minus", slopes.a_minus, digits);
    row("a_plus (" + (slopes.a_plus_family.empty() ? std::string("?") : slopes.a_plus_family) + ")", slopes.a_plus, digits);
    row("paper closed a_minus", slopes.closed_minus, digits);
    row("paper closed a_plus", slopes.closed_plus, digits);
    std::cout << "  a_minus vs closed form: " << agreement_word(slopes.minus_vs_closed)
              << "; vs printed -0.02941...: " << agreement_word(slopes.minus_printed.truncated) << "\n";
    std::cout << "  a_plus vs closed form: " << agreement_word(slopes.plus_vs_closed)
              << "; vs printed 0.3555...: " << agreement_word(slopes.plus_printed.truncated)
              << "; closed form vs printed: " << agreement_word(slopes.closed_plus_printed.truncated) << "\n";
}

int run(const SlopesOptions& options) {
    if (!options.certificate.empty()) {
        require_output_paths({{"--certificate", options.certificate}});
        require_rounding_self_test();
    }
    return with_field(options.digits, max_digits, [&](const auto& field, long digits) {
        const auto slopes = decided(within_contract([&] { return certify_sphere_slopes(field); }), field, digits, max_digits);
        if (options.json) {
            Json document = header_json("slopes", field, digits);
            document.update(sphere_slopes_json(slopes));
            print_json(document);
        } else {
            print_table(slopes, table_digits(digits, !options.digits.empty()));
        }
        if (!slopes.a_minus || !slopes.a_plus) throw Failure(exit_undecided, "slopes: undecided at this precision");
        if (!options.certificate.empty())
            write_certificate_or_fail(options.certificate, field, digits, max_digits,
                                      [&] { return sphere_slopes_certificate(slopes, field, digits); });
        return exit_ok;
    });
}

}  // namespace

void add_slopes(CLI::App& app) {
    auto options = std::make_shared<SlopesOptions>();
    CLI::App* command =
        app.add_subcommand("slopes", "One-sided slopes a_minus, a_plus of the maximal density at p = 1 vs the paper");
    add_digits_option(*command, options->digits, max_digits);
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    add_output_option(*command, "--certificate", options->certificate,
                      "write a certificate of the slopes (replay it with `superpack verify FILE`); nothing when undecided");
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("slopes", add_slopes);
}  // namespace

}  // namespace superpack::cli
