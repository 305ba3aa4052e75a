// The sphere pairs: against another sphere, and against the ground.

#include "collision/collision.hpp"

namespace impulse {

void sphere_and_sphere(const Sphere& sa, const Placement& pa, int a, const Sphere& sb, const Placement& pb, int b,
                       std::vector<Contact>& out) {
    const Vec3 between = pa.position - pb.position;
    const double distance = between.norm();
    const double penetration = sa.radius + sb.radius - distance;
    if (penetration < 0.0) return;
    // Concentric spheres have no direction to part along; +y is as good as any and is stated in the docs.
    const Vec3 normal = distance > 1e-12 ? Vec3(between / distance) : Vec3::UnitY();
    Contact c;
    c.bodies = {a, b};
    c.normal = normal;
    c.penetration = penetration;
    // Body b's surface is at pb + n r_b, body a's at pb + n (r_b - penetration); the point is midway.
    c.point = pb.position + normal * (sb.radius - 0.5 * penetration);
    c.origin = {CollisionTest::sphere_sphere, {Feature{FeatureKind::sphere, -1}, Feature{FeatureKind::sphere, -1}}};
    out.push_back(c);
}

void sphere_and_half_space(const Sphere& s, const Placement& p, int a, const HalfSpace& ground,
                           std::vector<Contact>& out) {
    const double height = ground.normal.dot(p.position) - ground.offset;  // centre above the plane
    const double penetration = s.radius - height;
    if (penetration < 0.0) return;
    Contact c;
    c.bodies = {a, world_body};
    c.normal = ground.normal;
    c.penetration = penetration;
    c.point = p.position - ground.normal * s.radius;  // the sphere's deepest point
    c.origin = {CollisionTest::sphere_half_space, {Feature{FeatureKind::sphere, -1}, Feature{FeatureKind::plane, -1}}};
    out.push_back(c);
}

}  // namespace impulse
