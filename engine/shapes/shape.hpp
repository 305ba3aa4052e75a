#pragma once
// Collision shapes in body space (centred on the body's centre of mass), and the static ground.

#include "math/types.hpp"

#include <array>

#include <variant>

namespace impulse {

struct Sphere {
    double radius;  // m

    bool operator==(const Sphere&) const = default;
};

struct Box {
    Vec3 half_size;  // m, along the body's x, y, z axes

    bool operator==(const Box&) const = default;
};

using Shape = std::variant<Sphere, Box>;

// The solid n . x <= offset: the ground (n = +y, offset 0) is everything below y = 0.
struct HalfSpace {
    Vec3 normal = Vec3::UnitY();  // unit, pointing out of the solid
    double offset = 0.0;          // m

    bool operator==(const HalfSpace&) const = default;
};

// The exact inverse inertia of a solid shape of inverse mass m^-1, in body axes:
// sphere I = 2/5 m r^2; box with half-sizes (a, b, c): I = diag(m (b^2 + c^2), m (a^2 + c^2), m (a^2 + b^2)) / 3.
// An immovable body (m^-1 = 0) gets zero.
Mat3 solid_inverse_inertia(const Shape& shape, double inverse_mass);
Mat3 sphere_inverse_inertia(double inverse_mass, double radius);
Mat3 box_inverse_inertia(double inverse_mass, const Vec3& half_size);

// The radius of a sphere about the centre that holds the whole shape (for the broad phase).
double bounding_radius(const Shape& shape);

// Box features, numbered the same way everywhere (traces, tests, lessons):
//   vertex i: x = -a if bit 0 of i else +a, y likewise with bit 1, z with bit 2
//             (the reference engine's order (+,+,+), (-,+,+), (+,-,+), (-,-,+), (+,+,-), ...);
//   face f:   0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z;
//   edge e:   along axis e / 4 (0 x, 1 y, 2 z); the other two coordinates take their signs from bits 0 and 1
//             of e % 4, in axis order (for an x edge: bit 0 gives y, bit 1 gives z).
Vec3 box_vertex(const Vec3& half_size, int vertex);
int box_face(int axis, bool negative);
// The edge along `axis` whose other coordinates are negative where `negative` (per axis, 0 or 1) says.
int box_edge(int axis, const std::array<int, 3>& negative);

}  // namespace impulse
