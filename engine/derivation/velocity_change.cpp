#include "derivation/velocity_change.hpp"

// u = q_rel x g  (14.2), delta p-dot = g m^-1  (7.5), delta theta-dot = I^-1 u  (14.1), for +g on body 0 and -g
// on body 1.

namespace impulse {

VelocityChange velocity_change(const Vec3& impulse_world, const PerBody<Vec3>& relative_position,
                               const PerBody<MassProperties>& mass) {
    const std::array<bool, 2> bodies = present(relative_position);
    const auto impulse_on = [&](int i) -> Vec3 { return body_sign(i) * impulse_world; };  // +-g
    const PerBody<Vec3> torque =
        per_body(bodies, [&](int i) -> Vec3 { return relative_position[i]->cross(impulse_on(i)); });  // (14.2)
    return {.impulsive_torque = torque,
            .velocity_change = per_body(bodies, [&](int i) -> Vec3 { return impulse_on(i) * mass[i]->inverse_mass; }),
            .rotation_change =
                per_body(bodies, [&](int i) -> Vec3 { return mass[i]->inverse_inertia_world * *torque[i]; })};
}

}  // namespace impulse
