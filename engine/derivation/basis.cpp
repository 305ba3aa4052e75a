#include "derivation/basis.hpp"

#include <cmath>

namespace impulse {

Basis basis(const Vec3& unit_normal) {
    Basis b;
    const Vec3& n = unit_normal;
    Vec3 seed_cross;
    if (std::abs(n.x()) > std::abs(n.y())) {
        b.seed = TangentSeed::world_y;
        seed_cross = cross(Vec3(0.0, 1.0, 0.0), n);  // (n.z, 0, -n.x)
    } else {
        b.seed = TangentSeed::world_x;
        seed_cross = cross(Vec3(1.0, 0.0, 0.0), n);  // (0, -n.z, n.y)
    }
    // Normalised as Eigen's normalized() does: each component divided by the root of the sum of squares, a zero
    // vector left as it is (never, for a unit normal: its length is at least 1/sqrt(2)).
    const double squared_length = dot(seed_cross, seed_cross);
    if (squared_length > 0.0) {
        const double length = std::sqrt(squared_length);
        seed_cross = Vec3(seed_cross.x() / length, seed_cross.y() / length, seed_cross.z() / length);
    }
    b.contact_to_world.col(0) = n;
    b.contact_to_world.col(1) = seed_cross;
    b.contact_to_world.col(2) = cross(n, seed_cross);
    return b;
}

}  // namespace impulse
