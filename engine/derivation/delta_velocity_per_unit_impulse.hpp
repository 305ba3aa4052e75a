#pragma once
// Step 3, the per-unit-impulse chain: how fast the contact points separate along the normal when a unit
// impulse acts along the normal (+n on body 0, -n on body 1). The chapter's "Velocity Change By Impulse".

#include "math/products.hpp"
#include "math/types.hpp"

#include <array>

namespace impulse {

// What the chain needs of one body: its mass properties at the time the contact is prepared.
struct MassProperties {
    double inverse_mass = 0.0;                  // m^-1
    Mat3 inverse_inertia_world = Mat3::Zero();  // I^-1 in world axes

    bool operator==(const MassProperties&) const = default;
};

// A contact's two bodies' mass, as the kernel reads it: body 1 null for the world.
using ContactMass = std::array<const MassProperties*, 2>;

struct UnitImpulseResponse {
    Vec3 torque_per_unit_impulse;          // u = q_rel x n  (14.2)
    Vec3 rotation_per_unit_impulse;        // I^-1 u  (14.1): change of angular velocity
    Vec3 point_velocity_per_unit_impulse;  // (I^-1 u) x q_rel  (9.5): velocity of the contact point from that rotation
    double angular_component;              // point_velocity_per_unit_impulse . n
    double linear_component;               // m^-1

    bool operator==(const UnitImpulseResponse&) const = default;
};

struct UnitImpulseChain {
    PerBody<UnitImpulseResponse> bodies;
    double delta_velocity_per_unit_impulse;  // d = sum over bodies of (linear + angular component)

    bool operator==(const UnitImpulseChain&) const = default;
};

// The chain for one body. Body 1 receives -n, which negates u, I^-1 u and the point velocity; its point
// moving the opposite way then adds the same positive amount to the separating speed, so both bodies
// use +n here and the components simply add. (Inline, in plain doubles: every method's preparation and the
// recorder compute step 3 through it, math/products.hpp.)
IMPULSE_KERNEL UnitImpulseResponse unit_impulse_response(const Vec3& normal, const Vec3& relative_position,
                                                         const MassProperties& mass) {
    UnitImpulseResponse r;
    r.torque_per_unit_impulse = cross(relative_position, normal);  // u = q_rel x n  (14.2)
    r.rotation_per_unit_impulse = times(mass.inverse_inertia_world, r.torque_per_unit_impulse);  // I^-1 u  (14.1)
    r.point_velocity_per_unit_impulse = cross(r.rotation_per_unit_impulse, relative_position);   // w x q_rel  (9.5)
    r.angular_component = dot(r.point_velocity_per_unit_impulse, normal);
    r.linear_component = mass.inverse_mass;
    return r;
}

// d = the sum over the bodies of their angular and linear components, in the reference engine's order (angular
// then linear, body 0 then body 1) so the last bit of d matches it; `body1` null for the world.
IMPULSE_KERNEL double delta_velocity_per_unit_impulse(const UnitImpulseResponse& body0,
                                                      const UnitImpulseResponse* body1) {
    double d = 0.0;
    d += body0.angular_component;
    d += body0.linear_component;
    if (body1) {
        d += body1->angular_component;
        d += body1->linear_component;
    }
    return d;
}

// d alone, for a contact whose bodies' relative positions are `relative_position` (body 1's unread for the world).
IMPULSE_KERNEL double delta_velocity_per_unit_impulse(const Vec3& normal, const std::array<Vec3, 2>& relative_position,
                                                      const ContactMass& mass) {
    const UnitImpulseResponse body0 = unit_impulse_response(normal, relative_position[0], *mass[0]);
    if (!mass[1]) return delta_velocity_per_unit_impulse(body0, nullptr);
    const UnitImpulseResponse body1 = unit_impulse_response(normal, relative_position[1], *mass[1]);
    return delta_velocity_per_unit_impulse(body0, &body1);
}

// The chain with every intermediate (what the recorder keeps).
UnitImpulseChain delta_velocity_per_unit_impulse(const Vec3& normal, const PerBody<Vec3>& relative_position,
                                                 const PerBody<MassProperties>& mass);

}  // namespace impulse
