#include "superpack/arith/enclosure_json.hpp"

#include "superpack/arith/decimal.hpp"
#include "superpack/arith/exact_ends.hpp"

namespace superpack {

namespace {

// An end exactly, or "inf" / "-inf" where the enclosure is unbounded; a NaN end, which bounds
// nothing, is the infinity on its side.
std::string end_text(mpfr_srcptr x, bool upper) {
    if (mpfr_number_p(x)) return dyadic_text(x);
    if (mpfr_inf_p(x)) return mpfr_sgn(x) > 0 ? "inf" : "-inf";
    return upper ? "inf" : "-inf";
}

template <class I>
Json enclosure(const I& x, long bits) {
    const DecimalEnclosure text = to_decimal(x, printed_digits(bits));
    const ExactEnds ends(x);
    return Json{{"lo", text.lo}, {"hi", text.hi}, {"lo_exact", end_text(ends.lo(), false)}, {"hi_exact", end_text(ends.hi(), true)}};
}
}  // namespace

Json enclosure_json(const DInterval& x) { return enclosure(x, 53); }
Json enclosure_json(const Ball& x) { return enclosure(x, x.precision()); }

}  // namespace superpack
