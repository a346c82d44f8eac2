#include "superpack/problems/periodic/end_state.hpp"

namespace superpack {

namespace {

constexpr int cell_bits = 40, quaternion_bits = 30;

PeriodicPacking exact_packing(const Rational& p, const SimulationEndState& state) {
    PeriodicPacking packing;
    packing.p = p;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) packing.cell[i][j] = dyadic_near(state.cell[i][j], cell_bits);
    for (std::size_t n = 0; n < state.fractional.size(); ++n) {
        RationalVector3 center;
        std::array<Rational, 3> fraction;
        for (int c = 0; c < 3; ++c) fraction[c] = dyadic_near(state.fractional[n][c], cell_bits);
        for (int c = 0; c < 3; ++c)
            center[c] = fraction[0] * packing.cell[0][c] + fraction[1] * packing.cell[1][c] + fraction[2] * packing.cell[2][c];
        packing.centers.push_back(center);
        std::array<Rational, 4> quaternion;
        for (int c = 0; c < 4; ++c) quaternion[c] = dyadic_near(state.quaternions[n][c], quaternion_bits);
        packing.quaternions.push_back(quaternion);
    }
    return packing;
}

}  // namespace

PeriodicCertificate<DInterval> prove_end_state(const Rational& p, const SimulationEndState& end, const NormalGuess& guess) {
    return certify_periodic_packing(exact_packing(p, end), guess, DoubleField{});
}

}  // namespace superpack
