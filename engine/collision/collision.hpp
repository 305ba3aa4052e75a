#pragma once
// Contact generation: one small function per pair of shapes. Each appends what it finds to `out` with
// bodies {a, b} (b = world_body for the ground), the normal pointing from b towards a (the way a must move),
// the penetration, the contact point and its origin (the test and the features that touch). Materials are
// the world's business, not these tests'.
//
// Where the contact point goes (the same rule everywhere):
//   against the ground: ON the body's deepest point (a box's vertex, a sphere's lowest point), never beyond it;
//   between two bodies: midway between the two surfaces along the normal.

#include "contact/contact.hpp"
#include "shapes/shape.hpp"

#include <vector>

namespace impulse {

// Where a shape is: its body's centre and rotation (body -> world).
struct Placement {
    Vec3 position;
    Mat3 rotation;
};

void sphere_and_sphere(const Sphere& sa, const Placement& pa, int a, const Sphere& sb, const Placement& pb, int b,
                       std::vector<Contact>& out);
void sphere_and_half_space(const Sphere& s, const Placement& p, int a, const HalfSpace& ground,
                           std::vector<Contact>& out);
void box_and_half_space(const Box& box, const Placement& p, int a, const HalfSpace& ground, std::vector<Contact>& out);
void box_and_sphere(const Box& box, const Placement& pa, int a, const Sphere& s, const Placement& pb, int b,
                    std::vector<Contact>& out);
// `margin` (m, the setting speculative_margin): a face contact also keeps the clipped points up to this far outside
// the reference face, with negative penetration (speculative points); 0 keeps only the points that touch.
void box_and_box(const Box& ba, const Placement& pa, int a, const Box& bb, const Placement& pb, int b,
                 std::vector<Contact>& out, double margin = 0.0);
// The same contacts from the separating-axis test as it is defined, every axis's exact overlap: what box_and_box's
// screened test (it computes an exact overlap only where an estimate could decide otherwise) must agree with to
// the bit, kept as the readable statement of the test and as the reference tests/engine compares against.
void box_and_box_every_axis(const Box& ba, const Placement& pa, int a, const Box& bb, const Placement& pb, int b,
                            std::vector<Contact>& out, double margin = 0.0);

// Any two shapes; for a box and a sphere the box is made body 0 whichever order they come in. `margin`: two boxes'
// speculative points (box_and_box); the other pairs' single points need none.
void collide(const Shape& sa, const Placement& pa, int a, const Shape& sb, const Placement& pb, int b,
             std::vector<Contact>& out, double margin = 0.0);
void collide_with_ground(const Shape& s, const Placement& p, int a, const HalfSpace& ground, std::vector<Contact>& out);

}  // namespace impulse
