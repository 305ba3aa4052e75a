// Which pair test a pair of shapes needs.

#include "collision/collision.hpp"

namespace impulse {

void collide(const Shape& sa, const Placement& pa, int a, const Shape& sb, const Placement& pb, int b,
             std::vector<Contact>& out, double margin) {
    const auto* sphere_a = std::get_if<Sphere>(&sa);
    const auto* sphere_b = std::get_if<Sphere>(&sb);
    if (sphere_a && sphere_b) return sphere_and_sphere(*sphere_a, pa, a, *sphere_b, pb, b, out);
    if (!sphere_a && !sphere_b) return box_and_box(std::get<Box>(sa), pa, a, std::get<Box>(sb), pb, b, out, margin);
    // Box and sphere: the box is body 0 whichever came first.
    if (sphere_a) return box_and_sphere(std::get<Box>(sb), pb, b, *sphere_a, pa, a, out);
    return box_and_sphere(std::get<Box>(sa), pa, a, *sphere_b, pb, b, out);
}

void collide_with_ground(const Shape& s, const Placement& p, int a, const HalfSpace& ground,
                         std::vector<Contact>& out) {
    if (const auto* sphere = std::get_if<Sphere>(&s)) return sphere_and_half_space(*sphere, p, a, ground, out);
    return box_and_half_space(std::get<Box>(s), p, a, ground, out);
}

}  // namespace impulse
