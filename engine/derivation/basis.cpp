#include "derivation/basis.hpp"

#include <cmath>

namespace impulse {

Basis basis(const Vec3& unit_normal) {
    Basis b;
    b.normal = unit_normal;
    const Vec3& n = unit_normal;
    if (std::abs(n.x()) > std::abs(n.y())) {
        b.seed = TangentSeed::world_y;
        b.tangent1 = Vec3::UnitY().cross(n).normalized();  // (n.z, 0, -n.x) / sqrt(n.z^2 + n.x^2)
    } else {
        b.seed = TangentSeed::world_x;
        b.tangent1 = Vec3::UnitX().cross(n).normalized();  // (0, -n.z, n.y) / sqrt(n.z^2 + n.y^2)
    }
    b.tangent2 = n.cross(b.tangent1);
    b.contact_to_world.col(0) = b.normal;
    b.contact_to_world.col(1) = b.tangent1;
    b.contact_to_world.col(2) = b.tangent2;
    return b;
}

}  // namespace impulse
