#include "superpack/sim/periodic_images.hpp"

#include <cmath>
#include <stdexcept>

namespace superpack::sim {

std::vector<std::array<int, 3>> image_shifts(const Matrix3& cell, const Vector3& delta, double cutoff) {
    if (!std::isfinite(cutoff) || !std::isfinite(norm(delta)))
        throw std::invalid_argument("image_shifts: non-finite delta or cutoff");
    const double det = determinant(cell);
    const double volume_scale = norm(cell[0]) * norm(cell[1]) * norm(cell[2]);
    if (!std::isfinite(volume_scale) || !(std::fabs(det) > 1e-14 * volume_scale))
        throw std::invalid_argument("image_shifts: singular or non-finite cell");
    std::vector<std::array<int, 3>> shifts;
    if (!(cutoff > 0)) return shifts;
    const Matrix3 inverse_rows = transpose(inverse(cell));  // row m: column m of cell^-1
    const double reach = cutoff + norm(delta);
    std::array<int, 3> bound{};
    double entries = 1;
    for (int m = 0; m < 3; ++m) {
        // A hair over the bound, so that rounding in it cannot drop a shift at the edge.
        const double limit = std::floor(norm(inverse_rows[m]) * reach * (1 + 1e-12));
        entries *= 2 * limit + 1;
        if (!(entries <= 1e6)) throw std::invalid_argument("image_shifts: more than 10^6 candidate shifts (cutoff too large for the cell)");
        bound[m] = static_cast<int>(limit);
    }
    const double cutoff_squared = cutoff * cutoff;
    for (int i = -bound[0]; i <= bound[0]; ++i)
        for (int j = -bound[1]; j <= bound[1]; ++j)
            for (int k = -bound[2]; k <= bound[2]; ++k) {
                const Vector3 x = delta + row_combination(cell, Vector3{double(i), double(j), double(k)});
                if (dot(x, x) < cutoff_squared) shifts.push_back({i, j, k});
            }
    return shifts;
}

}  // namespace superpack::sim
