#pragma once
// The broad phase: which pairs of bodies are close enough to be worth a pair test, found from each shape's
// world-axis bounding box. Its cost is a profile figure, never part of a trace: the pairs it returns are exactly
// those whose boxes overlap, so how it finds them can change without changing one bit of any run.
//
// How: a uniform grid, rebuilt each frame (broad_phase.cpp). We used to sort the boxes on their low x and sweep
// along x (sort and sweep, or sweep and prune: Baraff's 1992 thesis; I-COLLIDE, Cohen et al. 1995). A sweep tests
// every pair whose intervals overlap along its one axis, and a scene spread over two axes defeats it: on Box3D's
// large pyramid (5050 cubes, 100 layers in the x-y plane) a cube's x-interval meets one or two cubes of every layer,
// so the sweep made 420,000 tests a frame (83 a cube) to find 14,737 pairs. Box2D v3 and Box3D keep a dynamic
// bounding-volume tree whose boxes are enlarged, so that most bodies stay inside theirs from step to step; they
// query the tree only for the bodies that left theirs, and keep the pairs found in earlier steps. That is cheap
// because it remembers, and so it needs the bookkeeping of what changed. Ours finds every pair afresh from this
// frame's boxes, with nothing kept between frames to fall out of step: a grid whose cells are a little longer than
// the longest side lists each body once, in the cell of its box's low corner, and any body whose box meets it has
// its low corner in one of the 27 cells around that one. On the pyramid that is about nine bodies to look at, half
// of them before it in the index order and so skipped: a few tests a body, whatever the scene's layout. The
// bodies much larger than the rest (a ground slab, a long plank) would force cells of their size; they are tested
// against every body instead, and the cells follow the others. Each body's pairs are collected in index order, so
// the list comes out sorted without sorting it.

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
