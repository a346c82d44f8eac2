#include "checker/core/render.hpp"

#include <algorithm>

#include "checker/core/replay.hpp"

namespace superpack_checker {

namespace {

// One end, rounded in the stated direction by MPFR's own decimal conversion. A zero end is
// written as +0 (MPFI keeps an upper end 0 as -0; the file's "0" has no sign).
std::string end_text(mpfr_srcptr x, const char* pattern, int digits) {
    mpfr_t value;
    mpfr_init2(value, mpfr_get_prec(x));
    mpfr_set(value, x, MPFR_RNDN);  // exact: same precision
    if (mpfr_zero_p(value)) mpfr_set_zero(value, 1);
    char* text = nullptr;
    const int length = mpfr_asprintf(&text, pattern, digits, value);
    std::string result = length >= 0 ? std::string(text) : std::string("nan");
    if (length >= 0) mpfr_free_str(text);
    mpfr_clear(value);
    return result;
}

}  // namespace

std::string decimal_field(const Real& x) {
    return "[" + end_text(x.lo(), "%.*RDe", 16) + ", " + end_text(x.hi(), "%.*RUe", 16) + "]";
}

std::string enclosure_words(const Real& x) {
    return "[" + end_text(x.lo(), "%.*RDg", 17) + ", " + end_text(x.hi(), "%.*RUg", 17) + "]";
}

std::string lower_end_words(const Real& x) { return end_text(x.lo(), "%.*RDg", 17); }
std::string upper_end_words(const Real& x) { return end_text(x.hi(), "%.*RUg", 17); }

std::string exact_text(const mpq_class& q) {
    // A reduced a/b is a terminating decimal iff b = 2^i 5^j; it then has max(i, j) places.
    mpz_class rest = q.get_den();
    const unsigned long twos = mpz_remove(rest.get_mpz_t(), rest.get_mpz_t(), mpz_class(2).get_mpz_t());
    const unsigned long fives = mpz_remove(rest.get_mpz_t(), rest.get_mpz_t(), mpz_class(5).get_mpz_t());
    if (rest != 1) return q.get_str();
    const unsigned long places = std::max(twos, fives);
    mpz_class scale;
    mpz_ui_pow_ui(scale.get_mpz_t(), 10, places);
    const mpz_class scaled = abs(q.get_num()) * scale / q.get_den();  // exact
    std::string digits = scaled.get_str();
    if (places > 0) {
        if (digits.size() <= places) digits.insert(0, places + 1 - digits.size(), '0');
        digits.insert(digits.size() - places, ".");
    }
    return (q < 0 ? "-" : "") + digits;
}

std::string rational_words(const mpq_class& q) {
    const std::string exact = exact_text(q);
    if (exact.find('/') == std::string::npos) return exact;
    mpz_class scale, truncated;
    mpz_ui_pow_ui(scale.get_mpz_t(), 10, 12);
    mpz_tdiv_q(truncated.get_mpz_t(), mpz_class(abs(q.get_num()) * scale).get_mpz_t(), q.get_den_mpz_t());
    std::string digits = truncated.get_str();
    if (digits.size() <= 12) digits.insert(0, 13 - digits.size(), '0');
    digits.insert(digits.size() - 12, ".");
    return exact + " (" + (q < 0 ? "-" : "") + digits + "...)";
}

Real proved_enclosure(Context& context, const Json& stated, const std::string& path, const Real& own) {
    check_encloses(context, stated, path, own);
    return context.interval(stated, path);
}

Real proved_below(Context& context, const Json& stated, const std::string& path, const Real& own, long bound) {
    const Real claimed = proved_enclosure(context, stated, path, own);
    context.require(less(claimed, integer(bound, context.precision())), path,
                    "the stated enclosure " + text(claimed) + " is not certainly < " + std::to_string(bound) +
                        ", which the claim says of it (the checker's: " + text(own) + ")");
    return claimed;
}

void check_p_decimal(Context& context, const Json& inputs, const mpq_class& p) {
    const std::string stated = context.string_at(inputs, "p_decimal", "inputs");
    context.require(stated == exact_text(p), "inputs.p_decimal", "\"" + stated.substr(0, 60) + "\" is not p = " + exact_text(p));
}

}  // namespace superpack_checker
