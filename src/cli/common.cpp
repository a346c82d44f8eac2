#include "common.hpp"

#include "superpack/arith/self_test.hpp"

namespace superpack::cli {

Rational parse_p(const std::string& text) {
    const Rational p = parse_rational(text);
    if (p <= 0) throw InputError("p must be positive, got '" + text + "'");
    return p;
}

long parse_digits(const std::string& text) {
    bool digits_only = !text.empty() && text.size() <= 6;
    for (char c : text) digits_only = digits_only && c >= '0' && c <= '9';
    const long digits = digits_only ? std::stol(text) : 0;
    if (digits < 1 || digits > 100000)
        throw InputError("--digits must be a whole number from 1 to 100000, got '" + text + "'");
    return digits;
}

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
        throw Failure(exit_invalid, "rounding self-test failed (" + report.failures.front() + "); no certificate written");
}

}  // namespace superpack::cli
