// The one split rule of every subdivision in superpack: cut the widest component of a box at
// its midpoint. Certificates of partitions replay it (cert/certificate_partition.hpp), so it
// lives in one place.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "superpack/arith/interval.hpp"

namespace superpack {

// The index of the widest component (the first of equals).
template <class I>
std::size_t widest_component(const std::vector<I>& box) {
    std::size_t widest = 0;
    for (std::size_t k = 1; k < box.size(); ++k)
        if (width_upper(box[k]) > width_upper(box[widest])) widest = k;
    return widest;
}

// The two halves of box, cut at the midpoint of its widest component; they share that point.
template <class I>
std::pair<std::vector<I>, std::vector<I>> bisect_widest(const std::vector<I>& box) {
    const std::size_t widest = widest_component(box);
    const I center = midpoint(box[widest]);
    std::pair<std::vector<I>, std::vector<I>> halves{box, box};
    halves.first[widest] = hull(lower_point(box[widest]), center);
    halves.second[widest] = hull(center, upper_point(box[widest]));
    return halves;
}

// The midpoint of every component: a point of the box (each component a point interval).
template <class I>
std::vector<I> center_of(const std::vector<I>& box) {
    std::vector<I> center;
    for (const I& x : box) center.push_back(midpoint(x));
    return center;
}

}  // namespace superpack
