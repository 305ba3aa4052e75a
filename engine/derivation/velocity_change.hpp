#pragma once
// Step 7, `velocity_change` and `rotation_change`: the impulse split into each body's linear and angular
// response. Body 0 receives +g, body 1 receives -g.

#include "derivation/delta_velocity_per_unit_impulse.hpp"
#include "math/lanes.hpp"
#include "math/types.hpp"

namespace impulse {

struct VelocityChange {
    PerBody<Vec3> impulsive_torque;  // u = q_rel x (+-g)  (14.2)
    PerBody<Vec3> velocity_change;   // delta p-dot = (+-g) m^-1  (7.5)
    PerBody<Vec3> rotation_change;   // delta theta-dot = I^-1 u  (14.1)

    bool operator==(const VelocityChange&) const = default;
};

// Step 7 for one body, given the impulse it receives (+g for body 0, -g for body 1), world: u = q_rel x g (14.2),
// g m^-1 (7.5), I^-1 u (14.1). Inline, in plain doubles (math/products.hpp): the book's step 7 and every
// accumulating method's visits apply impulses through it.
template <typename V>
struct BodyVelocityChangeOf {
    V impulsive_torque;
    V velocity_change;
    V rotation_change;
};
using BodyVelocityChange = BodyVelocityChangeOf<Vec3>;

// Over a Vec3 and a body's MassProperties, or four lanes' (math/lanes.hpp).
template <typename V, typename Real, typename Inertia>
IMPULSE_KERNEL BodyVelocityChangeOf<V> body_velocity_change_of(const V& impulse, const V& relative_position,
                                                               Real inverse_mass, const Inertia& inverse_inertia) {
    const V u = cross(relative_position, impulse);
    const Real m = inverse_mass;
    return {u, {impulse.x() * m, impulse.y() * m, impulse.z() * m}, times(inverse_inertia, u)};
}

IMPULSE_KERNEL BodyVelocityChange body_velocity_change(const Vec3& impulse, const Vec3& relative_position,
                                                       const MassProperties& mass) {
    return body_velocity_change_of<Vec3>(impulse, relative_position, mass.inverse_mass, mass.inverse_inertia_world);
}

// Follows equation 14.2, u = q_rel x g. (The chapter's code snippet writes g x q_rel, which has the
// opposite sign; the reference engine's code agrees with the equation.)
VelocityChange velocity_change(const Vec3& impulse_world, const PerBody<Vec3>& relative_position,
                               const PerBody<MassProperties>& mass);

}  // namespace impulse
