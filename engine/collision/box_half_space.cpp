// A box against the ground: one contact for every vertex at or below the plane, at the vertex itself, in
// vertex order. A box lying flat gives 4, on an edge 2, on a corner 1.

#include "collision/collision.hpp"

namespace impulse {

void box_and_half_space(const Box& box, const Placement& p, int a, const HalfSpace& ground, std::vector<Contact>& out) {
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
