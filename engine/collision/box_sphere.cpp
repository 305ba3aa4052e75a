// A box against a sphere: the point of the box closest to the sphere's centre decides. Body 0 is the box.

#include "collision/collision.hpp"

#include <cmath>

namespace impulse {

namespace {

// Which feature of the box a point in box coordinates lies on: how many of its coordinates sit on a face.
Feature box_feature_at(const Vec3& local, const Vec3& h) {
    int on_faces = 0, face = -1, vertex = 0;
    std::array<int, 3> signs{};
    for (int axis = 0; axis < 3; ++axis) {
        const bool negative = local[axis] < 0.0;
        signs[static_cast<std::size_t>(axis)] = negative ? 1 : 0;
        // On the face to rounding: a centre exactly on a turned box's edge lands a hair inside or out.
        if (std::abs(local[axis]) >= h[axis] * (1.0 - 1e-9)) {
            ++on_faces;
            face = box_face(axis, negative);
        }
        vertex |= (negative ? 1 : 0) << axis;
    }
    if (on_faces == 1) return {FeatureKind::face, face};
    if (on_faces == 3) return {FeatureKind::vertex, vertex};
    // An edge: along the one axis whose coordinate is strictly inside.
    int along = 0;
    for (int axis = 0; axis < 3; ++axis)
        if (std::abs(local[axis]) < h[axis] * (1.0 - 1e-9)) along = axis;
    return {FeatureKind::edge, box_edge(along, signs)};
}

}  // namespace

void box_and_sphere(const Box& box, const Placement& pa, int a, const Sphere& s, const Placement& pb, int b,
                    std::vector<Contact>& out) {
    const Vec3& h = box.half_size;
    const Vec3 centre = pa.rotation.transpose() * (pb.position - pa.position);  // sphere centre, box coordinates
    const Vec3 closest = centre.cwiseMax(-h).cwiseMin(h);
    Vec3 normal_local;
    double penetration;
    Vec3 surface = closest;
    if (closest != centre) {
        // Outside the box: the normal runs from the sphere's centre to the box's surface, pushing the box away.
        const Vec3 towards_box = closest - centre;
        const double distance = towards_box.norm();
        penetration = s.radius - distance;
        if (penetration < 0.0) return;
        normal_local = towards_box / distance;
    } else {
        // The centre is inside the box: leave through the nearest face.
        int axis = 0;
        double nearest = h.x() - std::abs(centre.x());
        for (int k = 1; k < 3; ++k)
            if (h[k] - std::abs(centre[k]) < nearest) {
                nearest = h[k] - std::abs(centre[k]);
                axis = k;
            }
        const double side = centre[axis] < 0.0 ? -1.0 : 1.0;
        surface[axis] = side * h[axis];
        normal_local = Vec3::Zero();
        normal_local[axis] = -side;  // the box moves so that face passes back over the sphere
        penetration = s.radius + nearest;
    }
    Contact c;
    c.bodies = {a, b};
    c.normal = pa.rotation * normal_local;
    c.penetration = penetration;
    // The sphere's deepest point lies `penetration` beyond the box's surface point along n: midway is half.
    c.point = pa.position + pa.rotation * surface + c.normal * (0.5 * penetration);
    c.origin = {CollisionTest::box_sphere, {box_feature_at(surface, h), Feature{FeatureKind::sphere, -1}}};
    out.push_back(c);
}

}  // namespace impulse
