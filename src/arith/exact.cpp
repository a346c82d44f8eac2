#include "superpack/arith/exact.hpp"

#include <cctype>

namespace superpack {

namespace {

bool all_digits(const std::string& text) {
    if (text.empty()) return false;
    for (char c : text)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
}

Rational parse_decimal(const std::string& text, const std::string& original) {
    std::string body = text;
    long exponent = 0;
    const auto e = body.find_first_of("eE");
    if (e != std::string::npos) {
        std::string exponent_text = body.substr(e + 1);
        body = body.substr(0, e);
        bool negative_exponent = false;
        if (!exponent_text.empty() && (exponent_text[0] == '+' || exponent_text[0] == '-')) {
            negative_exponent = exponent_text[0] == '-';
            exponent_text = exponent_text.substr(1);
        }
        if (!all_digits(exponent_text) || exponent_text.size() > 6)
            throw InputError("not a number: '" + original + "'");
        exponent = std::stol(exponent_text) * (negative_exponent ? -1 : 1);
    }
    bool negative = false;
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) {
        negative = body[0] == '-';
        body = body.substr(1);
    }
    std::string integer_part = body, fraction_part;
    const auto dot = body.find('.');
    if (dot != std::string::npos) {
        integer_part = body.substr(0, dot);
        fraction_part = body.substr(dot + 1);
    }
    if ((integer_part.empty() && fraction_part.empty()) ||
        (!integer_part.empty() && !all_digits(integer_part)) ||
        (!fraction_part.empty() && !all_digits(fraction_part)))
        throw InputError("not a number: '" + original + "'");
    const mpz_class numerator(integer_part + fraction_part, 10);
    mpz_class scale;
    exponent -= static_cast<long>(fraction_part.size());
    mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(exponent < 0 ? -exponent : exponent));
    Rational value = exponent < 0 ? Rational(numerator, scale) : Rational(numerator * scale);
    value.canonicalize();
    return negative ? Rational(-value) : value;
}

}  // namespace

Rational parse_rational(const std::string& text) {
    std::string trimmed;
    for (char c : text)
        if (!std::isspace(static_cast<unsigned char>(c))) trimmed += c;
    if (trimmed.empty()) throw InputError("empty number");
    const auto slash = trimmed.find('/');
    if (slash == std::string::npos) return parse_decimal(trimmed, text);
    const Rational numerator = parse_decimal(trimmed.substr(0, slash), text);
    const Rational denominator = parse_decimal(trimmed.substr(slash + 1), text);
    if (denominator == 0) throw InputError("zero denominator in '" + text + "'");
    Rational value = numerator / denominator;
    value.canonicalize();
    return value;
}

std::string rational_text(const Rational& value) {
    Rational canonical = value;
    canonical.canonicalize();
    return canonical.get_str(10);
}

std::string decimal_or_fraction_text(const Rational& value) {
    // A rational is a terminating decimal iff its reduced denominator is 2^a 5^b.
    mpz_class denominator = value.get_den();
    unsigned long twos = mpz_remove(denominator.get_mpz_t(), denominator.get_mpz_t(), mpz_class(2).get_mpz_t());
    unsigned long fives = mpz_remove(denominator.get_mpz_t(), denominator.get_mpz_t(), mpz_class(5).get_mpz_t());
    if (denominator != 1) return rational_text(value);
    const unsigned long places = twos > fives ? twos : fives;
    mpz_class scale;
    mpz_ui_pow_ui(scale.get_mpz_t(), 10, places);
    mpz_class scaled = value.get_num() * scale / value.get_den();
    const bool negative = scaled < 0;
    if (negative) scaled = -scaled;
    std::string digits = scaled.get_str(10);
    if (places > 0) {
        if (digits.size() <= places) digits.insert(0, places + 1 - digits.size(), '0');
        digits.insert(digits.size() - places, ".");
    }
    return (negative ? "-" : "") + digits;
}

}  // namespace superpack
