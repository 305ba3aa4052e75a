#include "derivation/velocity_change.hpp"

// u = q_rel x g  (14.2), delta p-dot = g m^-1  (7.5), delta theta-dot = I^-1 u  (14.1), for +g on body 0 and -g
// on body 1.

namespace impulse {

VelocityChange velocity_change(const Vec3& impulse_world, const PerBody<Vec3>& relative_position,
                               const PerBody<MassProperties>& mass) {
    VelocityChange change;
    for (int i = 0; i < 2; ++i) {
        if (!relative_position[i]) continue;
        const Vec3 impulse_on = body_sign(i) * impulse_world;  // +-g
        const BodyVelocityChange body = body_velocity_change(impulse_on, *relative_position[i], *mass[i]);
        change.impulsive_torque[i] = body.impulsive_torque;
        change.velocity_change[i] = body.velocity_change;
        change.rotation_change[i] = body.rotation_change;
    }
    return change;
}

}  // namespace impulse
