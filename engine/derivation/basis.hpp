#pragma once
// Step 1, `basis`: contact coordinates from the contact normal.
//
// The chapter: "If we use this point as the origin, and the contact normal as one axis, we can form an
// orthonormal basis around it". Contact x is the normal; the two tangents span the contact plane, where
// friction acts. The basis matrix has the three axes as its COLUMNS, so it maps contact -> world, and its
// transpose maps world -> contact.

#include "math/products.hpp"
#include "math/types.hpp"

namespace impulse {

// Which world axis the normal was crossed with to seed tangent 1.
enum class TangentSeed { world_x, world_y };

struct Basis {
    TangentSeed seed;       // world axis used to build tangent 1
    Mat3 contact_to_world;  // columns (normal, tangent1, tangent2): each axis is kept once, as its column

    Vec3 normal() const { return contact_to_world.col(0); }    // contact x: the contact normal (unit)
    Vec3 tangent1() const { return contact_to_world.col(1); }  // contact y: normalise(seed x n)
    Vec3 tangent2() const { return contact_to_world.col(2); }  // contact z: n x tangent1

    bool operator==(const Basis&) const = default;
};

// Tangent construction (stated here, in the trace and in docs/trace-format.md):
//   if |n.x| > |n.y|: tangent1 = normalise(world Y x n)   (the normal leans towards X, so Y is far from it)
//   otherwise:        tangent1 = normalise(world X x n)
//   tangent2 = n x tangent1
// Crossing with the world axis the normal is farther from keeps the length before normalising at least
// 1/sqrt(2) for any unit normal, so no axis is ever degenerate. Unlike the reference engine, tangent 2 is
// the true cross product in both branches, so the basis is orthonormal and right-handed for every normal.
Basis basis(const Vec3& unit_normal);

// C^T v and C v: a vector in contact and in world coordinates, for the basis matrix C (contact_to_world).
inline Vec3 to_contact(const Mat3& contact_to_world, const Vec3& world) {
    return transposed_times(contact_to_world, world);
}
inline Vec3 to_world(const Mat3& contact_to_world, const Vec3& contact) {
    return times(contact_to_world, contact);
}
inline Vec3 to_contact(const Basis& b, const Vec3& world) {
    return to_contact(b.contact_to_world, world);
}
inline Vec3 to_world(const Basis& b, const Vec3& contact) {
    return to_world(b.contact_to_world, contact);
}

}  // namespace impulse
