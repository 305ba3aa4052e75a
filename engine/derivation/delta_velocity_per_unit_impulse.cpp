#include "derivation/delta_velocity_per_unit_impulse.hpp"

namespace impulse {

UnitImpulseResponse unit_impulse_response(const Vec3& normal, const Vec3& relative_position,
                                          const MassProperties& mass) {
    UnitImpulseResponse r;
    r.torque_per_unit_impulse = relative_position.cross(normal);                               // u = q_rel x n  (14.2)
    r.rotation_per_unit_impulse = mass.inverse_inertia_world * r.torque_per_unit_impulse;      // I^-1 u  (14.1)
    r.point_velocity_per_unit_impulse = r.rotation_per_unit_impulse.cross(relative_position);  // w x q_rel  (9.5)
    r.angular_component = r.point_velocity_per_unit_impulse.dot(normal);
    r.linear_component = mass.inverse_mass;
    return r;
}

UnitImpulseChain delta_velocity_per_unit_impulse(const Vec3& normal, const PerBody<Vec3>& relative_position,
                                                 const PerBody<MassProperties>& mass) {
    UnitImpulseChain chain{
        .bodies = per_body(present(relative_position),
                           [&](int i) { return unit_impulse_response(normal, *relative_position[i], *mass[i]); }),
        .delta_velocity_per_unit_impulse = 0.0};
    for (int i = 0; i < 2; ++i) {
        if (!chain.bodies[i]) continue;
        // Summed in the reference engine's order (angular then linear, body 0 then body 1) so the last bit
        // of d matches it.
        chain.delta_velocity_per_unit_impulse += chain.bodies[i]->angular_component;
        chain.delta_velocity_per_unit_impulse += chain.bodies[i]->linear_component;
    }
    return chain;
}

}  // namespace impulse
