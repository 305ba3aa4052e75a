#include "derivation/velocity_change.hpp"

namespace impulse {

VelocityChange velocity_change(const Vec3& impulse_world, const PerBody<Vec3>& relative_position,
                               const PerBody<MassProperties>& mass) {
    VelocityChange c;
    for (int i = 0; i < 2; ++i) {
        if (!relative_position[i]) continue;
        const Vec3 g = body_sign(i) * impulse_world;
        c.impulsive_torque[i] = relative_position[i]->cross(g);                          // u = q_rel x g  (14.2)
        c.velocity_change[i] = g * mass[i]->inverse_mass;                                // (7.5)
        c.rotation_change[i] = mass[i]->inverse_inertia_world * *c.impulsive_torque[i];  // I^-1 u  (14.1)
    }
    return c;
}

}  // namespace impulse
