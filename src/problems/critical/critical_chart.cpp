#include "superpack/problems/critical/critical_chart.hpp"

namespace superpack {

const char* configuration_name(MinkowskiCase configuration) {
    return configuration == MinkowskiCase::a3 ? "A3" : "W";
}

std::array<Coefficients, 6> configuration_triples(MinkowskiCase configuration) {
    if (configuration == MinkowskiCase::a3)
        return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, -1, 0}, {0, 1, -1}, {-1, 0, 1}}};
    return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}}};
}

}  // namespace superpack
