#include "superpack/arith/enclosure_json.hpp"

#include "superpack/arith/decimal.hpp"

namespace superpack {

namespace {
template <class I>
Json enclosure(const I& x, long bits) {
    const DecimalEnclosure text = to_decimal(x, printed_digits(bits));
    return Json{{"lo", text.lo}, {"hi", text.hi}};
}
}  // namespace

Json enclosure_json(const DInterval& x) { return enclosure(x, 53); }
Json enclosure_json(const Ball& x) { return enclosure(x, x.precision()); }

}  // namespace superpack
