// The JSON contract of superpack's output: every real is {"lo": "...", "hi": "..."} with lo
// rounded down and hi rounded up (decimal.hpp), at the digits the precision supports.
#pragma once
#include <nlohmann/json.hpp>

#include "superpack/arith/interval.hpp"

namespace superpack {

using Json = nlohmann::ordered_json;

Json enclosure_json(const DInterval& x);
Json enclosure_json(const Ball& x);

}  // namespace superpack
