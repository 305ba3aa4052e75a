#include "collision/broad_phase.hpp"

namespace impulse {

Bounds world_bounds(const Shape& shape, const Vec3& position, const Mat3& rotation) {
    Vec3 extent;
    if (const auto* sphere = std::get_if<Sphere>(&shape))
        extent = Vec3::Constant(sphere->radius);
    else  // a box's half-extents along the world axes: |R| h
        extent = rotation.cwiseAbs() * std::get<Box>(shape).half_size;
    return {position - extent, position + extent};
}

}  // namespace impulse
