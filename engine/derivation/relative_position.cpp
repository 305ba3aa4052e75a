#include "derivation/relative_position.hpp"

namespace impulse {

PerBody<Vec3> relative_position(const Vec3& contact_point, const PerBody<Vec3>& body_positions) {
    PerBody<Vec3> q_rel;
    for (int i = 0; i < 2; ++i)
        if (body_positions[i]) q_rel[i] = contact_point - *body_positions[i];  // q - p  (1.8)
    return q_rel;
}

}  // namespace impulse
