#pragma once
// The broad phase: which pairs of bodies are close enough to be worth a pair test, found from each shape's
// world-axis bounding box. Its cost is a profile figure, never part of a trace: the pairs it returns are exactly
// those whose boxes overlap, so how it finds them can change without changing one bit of any run.
//
// How: a uniform grid, rebuilt each frame (broad_phase.cpp). We used to sort the boxes on their low x and sweep
// along x (sort and prune: Baraff's 1992 thesis, I-COLLIDE's sweep and prune, Cohen et al. 1995). A sweep costs the
// boxes that overlap along its one axis, and a scene spread over two axes defeats it: on Box3D's large pyramid
// (5050 cubes, 100 layers in the x-y plane) every cube's x-interval meets two or three cubes in every layer, so
// the sweep tested about 300 candidates a cube to find six neighbours (1.9 ms a frame, Box3D 0.35 ms). Box2D v3
// and Box3D keep a dynamic bounding-volume tree whose boxes are enlarged so most bodies stay inside theirs, query
// only the bodies that left theirs, and keep the pairs found in earlier steps; that is cheap because it remembers.
// Ours finds every pair afresh from this frame's boxes, with nothing kept between frames to fall out of step: a
// grid whose cells are as big as the bodies puts each box in at most two cells along each axis, and a pair need
// only be tested where both boxes are, so the work is a few candidates a body whatever the scene's layout. Each
// pair is reported in one cell only, the cell holding the low corner of the two boxes' intersection (both boxes
// cover it), so no pair comes out twice. Bodies much larger than the rest (a ground slab, a long plank) would
// fill many cells; they are tested against every body directly instead, and the cell sizes follow the others.

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

// Pairs (i, j), i < j, whose bounds overlap, faces touching included (low <= high on each axis, both ways), in
// increasing order of i then j (so runs are deterministic). `bounds[k]` is empty for a body without a shape.
// Bounds that are not finite (a body whose state has become NaN) take part in no pair. Each bound's low must not
// exceed its high (as world_bounds makes them).
std::vector<std::pair<int, int>> overlapping_bounds(std::span<const std::optional<Bounds>> bounds);

// The overlapping pairs less those `skip(i, j)` drops as needing no test (two immovable bodies); still in order.
template <typename Skip>
std::vector<std::pair<int, int>> overlapping_pairs(std::span<const std::optional<Bounds>> bounds, Skip skip) {
    std::vector<std::pair<int, int>> pairs = overlapping_bounds(bounds);
    std::erase_if(pairs, [&skip](const std::pair<int, int>& pair) { return skip(pair.first, pair.second); });
    return pairs;
}

}  // namespace impulse
