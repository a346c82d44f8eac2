// The periodic images within a cutoff (sim/periodic_images.hpp), against enumeration of a box
// of shifts far larger than the bound the function derives.
#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <vector>

#include "superpack/sim/periodic_images.hpp"

using namespace superpack::sim;

namespace {

std::vector<std::array<int, 3>> enumerate_box(const Matrix3& cell, const Vector3& delta, double cutoff, int reach) {
    std::vector<std::array<int, 3>> shifts;
    for (int i = -reach; i <= reach; ++i)
        for (int j = -reach; j <= reach; ++j)
            for (int k = -reach; k <= reach; ++k)
                if (norm(delta + row_combination(cell, Vector3{double(i), double(j), double(k)})) < cutoff) shifts.push_back({i, j, k});
    return shifts;
}

}  // namespace

TEST_CASE("image shifts match brute force in a skewed cell") {
    // A strongly sheared cell: its third row leans far over the first two, so the shifts that
    // reach a point within the cutoff have large k0 and k1 for small k2.
    const Matrix3 skewed{Vector3{1.1, 0, 0}, Vector3{0.9, 0.7, 0}, Vector3{1.6, -1.2, 0.8}};
    const Matrix3 cube{Vector3{2, 0, 0}, Vector3{0, 2, 0}, Vector3{0, 0, 2}};
    int largest_shift = 0;
    for (const Matrix3& cell : {skewed, cube})
        for (const Vector3& delta : {Vector3{0, 0, 0}, Vector3{0.45, -0.3, 0.2}, Vector3{1.7, 1.2, -2.1}})
            for (double cutoff : {0.5, 2.0, 3.4, 4.5}) {
                INFO("delta (" << delta[0] << ", " << delta[1] << ", " << delta[2] << "), cutoff " << cutoff);
                std::vector<std::array<int, 3>> found = image_shifts(cell, delta, cutoff);
                const int reach = 40;
                const std::vector<std::array<int, 3>> expected = enumerate_box(cell, delta, cutoff, reach);
                CHECK(std::is_sorted(found.begin(), found.end()));
                CHECK(found == expected);
                for (const auto& shift : expected)
                    for (int k : shift) largest_shift = std::max(largest_shift, std::abs(k));
            }
    // The brute-force box is far larger than any shift found, and the skew matters: shifts far
    // from the origin are needed.
    CHECK(largest_shift < 30);
    CHECK(largest_shift >= 5);
    // The zero shift is there when delta itself is within the cutoff, and not otherwise.
    const auto near = image_shifts(skewed, {0.1, 0, 0}, 0.2);
    CHECK(std::find(near.begin(), near.end(), std::array<int, 3>{0, 0, 0}) != near.end());
    CHECK(image_shifts(skewed, {0.1, 0, 0}, 0.05).empty());
    CHECK(image_shifts(skewed, {0, 0, 0}, 0).empty());
}

TEST_CASE("image shifts refuse singular cells and boxes over 10^6 entries") {
    const Matrix3 flat{Vector3{1, 0, 0}, Vector3{0, 1, 0}, Vector3{1, 1, 0}};
    CHECK_THROWS_AS(image_shifts(flat, {0, 0, 0}, 1), std::invalid_argument);
    const Matrix3 nearly_flat{Vector3{1, 0, 0}, Vector3{0, 1, 0}, Vector3{1, 1, 1e-15}};
    CHECK_THROWS_AS(image_shifts(nearly_flat, {0, 0, 0}, 1), std::invalid_argument);
    const Matrix3 unit = identity_matrix();
    CHECK_THROWS_AS(image_shifts(unit, {0, 0, 0}, 60), std::invalid_argument);  // 121^3 > 10^6
    CHECK(image_shifts(unit, {0, 0, 0}, 40).size() > 250000);                      // 81^3 < 10^6
    CHECK_THROWS_AS(image_shifts(unit, {0, 0, 0}, std::nan("")), std::invalid_argument);
    CHECK_THROWS_AS(image_shifts(unit, {std::nan(""), 0, 0}, 1), std::invalid_argument);
}
