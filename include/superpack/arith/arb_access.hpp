// The arb_t inside a Ball, for the code that calls Arb itself (the Ball backend, conversions,
// tests). Everything else uses the operations of arith/interval.hpp and never sees Arb.
#pragma once
#include <arb.h>

#include "superpack/arith/ball.hpp"

namespace superpack {

inline arb_ptr arb_of(Ball& x) { return static_cast<arb_ptr>(x.storage()); }
inline arb_srcptr arb_of(const Ball& x) { return static_cast<arb_srcptr>(x.storage()); }

}  // namespace superpack
