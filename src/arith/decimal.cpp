#include "superpack/arith/decimal.hpp"
#include "superpack/arith/mpfr_bounds.hpp"

#include <cmath>
#include <cstdlib>

namespace superpack {

namespace {

std::string format(const mpfr_t value, int digits, bool up, bool fixed = false) {
    char* text = nullptr;
    // %R[DU][ef]: MPFR's own directed decimal conversion, one rounding in the stated direction.
    const char* pattern = fixed ? (up ? "%.*RUf" : "%.*RDf") : (up ? "%.*RUe" : "%.*RDe");
    const int length = mpfr_asprintf(&text, pattern, fixed ? digits : digits - 1, value);
    std::string result = length >= 0 ? std::string(text) : std::string("nan");
    mpfr_free_str(text);
    return result;
}

template <class I>
DecimalEnclosure decimal(const I& x, int digits, long bits, bool fixed = false) {
    mpfr_t lo, hi;
    mpfr_init2(lo, bits + 64);
    mpfr_init2(hi, bits + 64);
    get_bounds(lo, hi, x);
    DecimalEnclosure result{format(lo, digits, false, fixed), format(hi, digits, true, fixed)};
    mpfr_clear(lo);
    mpfr_clear(hi);
    return result;
}

template <class I>
std::string width(const I& x, long bits) {
    mpfr_t lo, hi;
    mpfr_init2(lo, bits + 64);
    mpfr_init2(hi, bits + 64);
    get_bounds(lo, hi, x);
    mpfr_sub(hi, hi, lo, MPFR_RNDU);
    std::string result = format(hi, 3, true);
    mpfr_clear(lo);
    mpfr_clear(hi);
    return result;
}

}  // namespace

int printed_digits(long bits) { return static_cast<int>(std::ceil(bits * 0.30103)) + 2; }

DecimalEnclosure to_decimal(const DInterval& x, int digits) { return decimal(x, digits, 53); }
DecimalEnclosure to_decimal(const mpfr_t lo, const mpfr_t hi, int digits) {
    return {format(lo, digits, false), format(hi, digits, true)};
}
DecimalEnclosure to_decimal(const Ball& x, int digits) { return decimal(x, digits, x.precision()); }
DecimalEnclosure to_fixed(const DInterval& x, int decimals) { return decimal(x, decimals, 53, true); }
DecimalEnclosure to_fixed(const Ball& x, int decimals) { return decimal(x, decimals, x.precision(), true); }
std::string width_text(const DInterval& x) { return width(x, 53); }
std::string width_text(const Ball& x) { return width(x, x.precision()); }

}  // namespace superpack
