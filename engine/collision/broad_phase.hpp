#pragma once
// The broad phase: which pairs of bodies are close enough to be worth a pair test. Sort and sweep along x
// over each shape's world-axis bounding box, then check y and z: about n log n instead of all n^2/2 pairs
// for the 1000-box scenes. Its cost is a profile figure, never part of a trace.

#include "shapes/shape.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace impulse {

struct Bounds {
    Vec3 low, high;
};

Bounds world_bounds(const Shape& shape, const Vec3& position, const Mat3& rotation);

// Pairs (i, j), i < j, whose bounds overlap, in increasing order of i then j (so runs are deterministic).
// `bounds[k]` is empty for a body without a shape; `skip(i, j)` drops pairs that need no test (two immovable
// bodies). Bounds that are not finite (a body whose state has become NaN) take part in no pair: sorting them
// would be meaningless.
template <typename Skip>
std::vector<std::pair<int, int>> overlapping_pairs(std::span<const std::optional<Bounds>> bounds, Skip skip) {
    std::vector<int> order;
    for (int k = 0; k < static_cast<int>(bounds.size()); ++k)
        if (const auto& b = bounds[static_cast<std::size_t>(k)]; b && b->low.allFinite() && b->high.allFinite())
            order.push_back(k);
    const auto low_x = [&bounds](int k) { return bounds[static_cast<std::size_t>(k)]->low.x(); };
    std::sort(order.begin(), order.end(),
              [&](int p, int q) { return low_x(p) < low_x(q) || (low_x(p) == low_x(q) && p < q); });

    std::vector<std::pair<int, int>> pairs;
    for (std::size_t s = 0; s < order.size(); ++s) {
        const Bounds& a = *bounds[static_cast<std::size_t>(order[s])];
        // Only the bodies that start before this one ends along x can overlap it.
        for (std::size_t t = s + 1; t < order.size() && low_x(order[t]) <= a.high.x(); ++t) {
            const Bounds& b = *bounds[static_cast<std::size_t>(order[t])];
            if (a.low.y() > b.high.y() || b.low.y() > a.high.y() || a.low.z() > b.high.z() || b.low.z() > a.high.z())
                continue;
            const int i = std::min(order[s], order[t]), j = std::max(order[s], order[t]);
            if (!skip(i, j)) pairs.emplace_back(i, j);
        }
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace impulse
