// The JSON contract of superpack's output: every real is {"lo": "...", "hi": "...", "lo_exact":
// "m*2^e", "hi_exact": "m*2^e"}: the decimals with lo rounded down and hi rounded up
// (decimal.hpp), at the digits the precision supports, and the interval's own ends exactly
// (exact_ends.hpp), which the Python package reads as Fractions.
#pragma once
#include <nlohmann/json.hpp>

#include "superpack/arith/interval.hpp"

namespace superpack {

using Json = nlohmann::ordered_json;

Json enclosure_json(const DInterval& x);
Json enclosure_json(const Ball& x);

}  // namespace superpack
