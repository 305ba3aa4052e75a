#pragma once
// Step 3, the per-unit-impulse chain: how fast the contact points separate along the normal when a unit
// impulse acts along the normal (+n on body 0, -n on body 1). The chapter's "Velocity Change By Impulse".

#include "math/types.hpp"

namespace impulse {

// What the chain needs of one body: its mass properties at the time the contact is prepared.
struct MassProperties {
    double inverse_mass = 0.0;                  // m^-1
    Mat3 inverse_inertia_world = Mat3::Zero();  // I^-1 in world axes

    bool operator==(const MassProperties&) const = default;
};

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
// use +n here and the components simply add.
UnitImpulseResponse unit_impulse_response(const Vec3& normal, const Vec3& relative_position,
                                          const MassProperties& mass);

UnitImpulseChain delta_velocity_per_unit_impulse(const Vec3& normal, const PerBody<Vec3>& relative_position,
                                                 const PerBody<MassProperties>& mass);

}  // namespace impulse
