// A box against the ground: one contact for every vertex at or below the plane, at the vertex itself, in
// vertex order. A box lying flat gives 4, on an edge 2, on a corner 1.

#include "collision/collision.hpp"

#include <cmath>

namespace impulse {

void box_and_half_space(const Box& box, const Placement& p, int a, const HalfSpace& ground, std::vector<Contact>& out) {
    // No vertex is within the half-diagonal |h| of the centre, so a box whose centre is higher above the plane than
    // that has no vertex at or below it, and the vertex tests would find nothing: most boxes of a stack or a pyramid
    // are not tested. The slack, a billionth of the lengths involved, is far more than the rounding of a vertex's
    // computed height, so no vertex the tests would find is skipped.
    const double n = ground.normal.norm();  // 1 for a scene's ground; kept general
    const double reach = n * box.half_size.norm();
    const double height = ground.normal.dot(p.position) - ground.offset;
    if (height > reach + 1e-9 * (std::abs(ground.offset) + n * p.position.norm() + reach)) return;
    for (int v = 0; v < 8; ++v) {
        const Vec3 vertex = p.position + p.rotation * box_vertex(box.half_size, v);
        const double penetration = ground.offset - ground.normal.dot(vertex);
        if (penetration < 0.0) continue;
        Contact c;
        c.bodies = {a, world_body};
        c.normal = ground.normal;
        c.penetration = penetration;
        c.point = vertex;
        c.origin = {CollisionTest::box_half_space, {Feature{FeatureKind::vertex, v}, Feature{FeatureKind::plane, -1}}};
        out.push_back(c);
    }
}

}  // namespace impulse
