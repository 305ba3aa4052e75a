#include "derivation/delta_velocity_per_unit_impulse.hpp"

namespace impulse {

UnitImpulseChain delta_velocity_per_unit_impulse(const Vec3& normal, const PerBody<Vec3>& relative_position,
                                                 const PerBody<MassProperties>& mass) {
    UnitImpulseChain chain{
        .bodies = per_body(present(relative_position),
                           [&](int i) { return unit_impulse_response(normal, *relative_position[i], *mass[i]); }),
        .delta_velocity_per_unit_impulse = 0.0};
    if (chain.bodies[0])
        chain.delta_velocity_per_unit_impulse =
            delta_velocity_per_unit_impulse(*chain.bodies[0], chain.bodies[1] ? &*chain.bodies[1] : nullptr);
    return chain;
}

}  // namespace impulse
