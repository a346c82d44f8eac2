#include "common.hpp"

#include <algorithm>

#include "superpack/arith/self_test.hpp"

namespace superpack::cli {

namespace {

bool printed_json = false;

}  // namespace

Rational parse_number(const std::string& text, const std::string& option) {
    if (text.size() > max_number_characters)
        throw InputError(option + ": a number has at most " + std::to_string(max_number_characters) + " characters, got " +
                         std::to_string(text.size()));
    return parse_rational(text);
}

Rational parse_p(const std::string& text, const std::string& option) {
    const Rational p = parse_number(text, option);
    if (p <= 0) throw InputError(option + ": p must be positive, got '" + text + "'");
    static const Rational smallest(1, 1000000), largest(1000000);
    if (p < smallest || p > largest)
        throw InputError(option + ": p = " + text + " is outside the supported range " + supported_p_text);
    return p;
}

std::vector<Rational> parse_scan(const std::string& text, std::size_t max_values) {
    const auto first = text.find(':'), second = text.find(':', first == std::string::npos ? 0 : first + 1);
    if (first == std::string::npos || second == std::string::npos)
        throw InputError("--scan wants a:b:h, got '" + text + "'");
    const Rational a = parse_p(text.substr(0, first), "--scan a"), b = parse_p(text.substr(first + 1, second - first - 1), "--scan b"),
                   h = parse_number(text.substr(second + 1), "--scan h");
    if (h <= 0) throw InputError("--scan a:b:h: the step h must be positive, got '" + text.substr(second + 1) + "'");
    if (b < a) throw InputError("--scan a:b:h needs a <= b");
    Rational count = (b - a) / h;
    count.canonicalize();
    if (count >= max_values)
        throw InputError("--scan: at most " + std::to_string(max_values) + " values of p, (b - a)/h + 1 is more");
    std::vector<Rational> values;
    for (Rational p = a; p <= b; p += h) values.push_back(p);
    return values;
}

long parse_digits(const std::string& text, long maximum) {
    bool digits_only = !text.empty() && text.size() <= 7;
    for (char c : text) digits_only = digits_only && c >= '0' && c <= '9';
    const long digits = digits_only ? std::stol(text) : 0;
    if (digits < 1 || digits > maximum)
        throw InputError("--digits must be a whole number from 1 to " + std::to_string(maximum) + " for this command, got '" +
                         text + "'");
    return digits;
}

void add_digits_option(CLI::App& command, std::string& digits, long maximum) {
    const CLI::Validator whole_digits(
        [maximum](std::string& text) {
            parse_digits(text, maximum);
            return std::string();
        },
        "", "digits");
    command.add_option("--digits", digits,
                       "significant digits, 1 to " + std::to_string(maximum) + " (Arb balls); default: binary64 intervals")
        ->check(whole_digits);
}

std::uint32_t parse_seed(const std::string& text) {
    const bool whole = !text.empty() && text.size() <= 10 && text.find_first_not_of("0123456789") == std::string::npos;
    if (!whole || std::stoull(text) > UINT32_MAX)
        throw InputError(std::string("--seed: a whole number from ") + seed_range_text + ", got '" + text.substr(0, 30) + "'");
    return static_cast<std::uint32_t>(std::stoull(text));
}

void add_seed_option(CLI::App& command, std::uint32_t& seed, const std::string& help) {
    command.add_option_function<std::string>(
        "--seed", [&seed](const std::string& text) { seed = parse_seed(text); }, help + "; " + seed_range_text);
}

std::string undecided_at_precision(const std::string& what, long digits, long maximum_digits) {
    const std::string precision = digits == 0 ? "binary64" : std::to_string(digits) + "-digit";
    std::string message = "undecided at " + precision + " precision (" + what +
                          ": an enclosure is too wide for the function's contract)";
    const long next = digits == 0 ? std::min(30L, maximum_digits) : std::min(2 * digits, maximum_digits);
    if (maximum_digits == 0) return message;  // a command without --digits
    if (next > digits)
        message += "; try --digits " + std::to_string(next);
    else
        message += "; --digits " + std::to_string(maximum_digits) + " is this command's limit";
    return message;
}

void print_json(const Json& document) {
    // Invalid UTF-8 typed by the user is replaced, never a reason to fail.
    std::cout << document.dump(2, ' ', false, Json::error_handler_t::replace) << "\n";
    printed_json = true;
}

bool json_printed() { return printed_json; }
void forget_printed_json() { printed_json = false; }

std::vector<std::pair<std::string, AddSubcommand>>& subcommand_registry() {
    static std::vector<std::pair<std::string, AddSubcommand>> registry;
    return registry;
}

SubcommandRegistration::SubcommandRegistration(const char* name, AddSubcommand add) {
    subcommand_registry().emplace_back(name, add);
}

void require_rounding_self_test() {
    const SelfTestReport report = run_rounding_self_test();
    if (!report.passed)
        throw Failure(exit_undecided, "rounding self-test failed (" + report.failures.front() +
                                          "): nothing can be certified on this machine");
}

}  // namespace superpack::cli
