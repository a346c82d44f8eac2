// A picture that could not be drawn: gnuplot missing, failing, too slow or writing no PNG, or a
// plot with nothing to draw. The message names the problem; the CLI maps it to exit code 2.
// Rendering has its own error type because it sits below the command line and knows no exit codes.
#pragma once
#include <stdexcept>

namespace superpack {

struct RenderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace superpack
