#include "superpack/sim/neighbour_regions.hpp"

#include <algorithm>
#include <cmath>

namespace superpack::sim {

namespace {

// Regions meet when their centres are closer than the sum of the radii, with room for the
// rounding of the centres and of the image offsets (a pair listed too many costs one screen).
constexpr double reach_margin = 1 + 1e-9;
// A new cell grid is laid when a region outgrows the design radius, for regions this much larger
// (so that growth lays few grids).
constexpr double design_growth = 1.25;

}  // namespace

void NeighbourRegions::build(const Matrix3& cell, const std::vector<Vector3>& centres, double radius) {
    cell_ = cell;
    inverse_ = inverse(cell);
    for (int m = 0; m < 3; ++m) column_norm_[m] = std::hypot(inverse_[0][m], inverse_[1][m], inverse_[2][m]);
    centres_ = centres;
    radii_.assign(centres.size(), radius);
    design_radius_ = design_growth * radius;
    bin_all();
    lists_.assign(centres.size(), {});
    for (std::size_t i = 0; i < centres.size(); ++i) lists_[i] = find(static_cast<int>(i));
}

void NeighbourRegions::bin_all() {
    // Cells at least 2 design radii thick in every direction: a plane of constant fractional
    // coordinate m lies 1 / |column m of B^-1| from the next one at distance 1.
    for (int m = 0; m < 3; ++m) counts_[m] = std::max(1, static_cast<int>(std::floor(1 / (column_norm_[m] * 2 * design_radius_ * reach_margin))));
    members_.assign(static_cast<std::size_t>(counts_[0]) * counts_[1] * counts_[2], {});
    home_.assign(centres_.size(), 0);
    for (std::size_t i = 0; i < centres_.size(); ++i) {
        home_[i] = cell_of(centres_[i]);
        members_[home_[i]].push_back(static_cast<int>(i));
    }
}

int NeighbourRegions::cell_of(const Vector3& centre) const {
    const Vector3 f = apply_transpose(inverse_, centre);
    std::array<int, 3> index{};
    for (int m = 0; m < 3; ++m) {
        const double wrapped = f[m] - std::floor(f[m]);
        index[m] = std::min(counts_[m] - 1, std::max(0, static_cast<int>(wrapped * counts_[m])));
    }
    return (index[0] * counts_[1] + index[1]) * counts_[2] + index[2];
}

std::vector<Neighbour> NeighbourRegions::find(int i) const {
    // The adjacent cells (mod m, each once: with fewer than 3 cells along an axis the
    // neighbours -1 and +1 coincide).
    const int home = home_[i];
    const std::array<int, 3> index{home / (counts_[1] * counts_[2]), (home / counts_[2]) % counts_[1], home % counts_[2]};
    std::array<std::vector<int>, 3> rows;
    for (int m = 0; m < 3; ++m) {
        for (int step = -1; step <= 1; ++step) {
            const int row = ((index[m] + step) % counts_[m] + counts_[m]) % counts_[m];
            if (std::find(rows[m].begin(), rows[m].end(), row) == rows[m].end()) rows[m].push_back(row);
        }
    }
    std::vector<Neighbour> found;
    for (int r0 : rows[0])
        for (int r1 : rows[1])
            for (int r2 : rows[2])
                for (int j : members_[(r0 * counts_[1] + r1) * counts_[2] + r2]) {
                    if (j == i) continue;
                    const double reach = (radii_[i] + radii_[j]) * reach_margin;
                    const Vector3 delta = centres_[j] - centres_[i];
                    // The images delta + k B within reach: |f_m + k_m| <= |column m of B^-1| reach.
                    const Vector3 f = apply_transpose(inverse_, delta);
                    std::array<int, 3> low{}, high{};
                    for (int m = 0; m < 3; ++m) {
                        low[m] = static_cast<int>(std::ceil(-f[m] - column_norm_[m] * reach));
                        high[m] = static_cast<int>(std::floor(-f[m] + column_norm_[m] * reach));
                    }
                    for (int k0 = low[0]; k0 <= high[0]; ++k0)
                        for (int k1 = low[1]; k1 <= high[1]; ++k1)
                            for (int k2 = low[2]; k2 <= high[2]; ++k2) {
                                const Vector3 offset = row_combination(cell_, Vector3{double(k0), double(k1), double(k2)});
                                if (norm(delta + offset) < reach) found.push_back(Neighbour{j, offset, {0, 0, 0}});
                            }
                }
    return found;
}

void NeighbourRegions::move(int i, const Vector3& centre, double radius) {
    for (const Neighbour& entry : lists_[i]) {
        auto& theirs = lists_[entry.partner];
        theirs.erase(std::remove_if(theirs.begin(), theirs.end(), [i](const Neighbour& n) { return n.partner == i; }), theirs.end());
    }
    centres_[i] = centre;
    radii_[i] = radius;
    if (radius > design_radius_) {
        design_radius_ = design_growth * radius;
        bin_all();
    } else {
        const int cell = cell_of(centre);
        if (cell != home_[i]) {
            auto& old = members_[home_[i]];
            old.erase(std::find(old.begin(), old.end(), i));
            members_[cell].push_back(i);
            home_[i] = cell;
        }
    }
    lists_[i] = find(i);
    for (const Neighbour& entry : lists_[i]) lists_[entry.partner].push_back(Neighbour{i, -1.0 * entry.offset, -1.0 * entry.normal});
}

}  // namespace superpack::sim
