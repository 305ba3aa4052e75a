#pragma once
// A rigid body as the resolver sees it: its state, and its mass properties in inverse form so that an
// immovable body (the ground, a wall) is simply zero.

#include "math/types.hpp"

namespace impulse {

struct RigidBody {
    Vec3 position = Vec3::Zero();                  // p: the centre of mass, world (m)
    Quat orientation = Quat::Identity();           // body -> world rotation
    Vec3 velocity = Vec3::Zero();                  // p-dot, world (m/s)
    Vec3 angular_velocity = Vec3::Zero();          // theta-dot, world (rad/s)
    double inverse_mass = 1.0;                     // m^-1 (1/kg); 0 = infinite mass
    Mat3 inverse_inertia_body = Mat3::Identity();  // I^-1 in body axes (1/(kg m^2)); 0 = cannot rotate
    Vec3 last_frame_acceleration = Vec3::Zero();   // acceleration the last integration applied (m/s^2), ch. 15

    bool operator==(const RigidBody&) const = default;
};

// I^-1 in world axes, R I^-1_body R^T: the tensor every derivation step uses.
Mat3 world_inverse_inertia(const RigidBody& body);

// Immovable = inverse mass 0 and zero inverse inertia: no impulse or move changes it.
bool is_immovable(const RigidBody& body);

// Kinetic energy 1/2 m v^2 + 1/2 w . I w; a body that cannot translate or rotate contributes nothing for
// that part. Needs the world inertia, so a body whose inverse inertia is singular but non-zero (a body
// that can rotate about only some axes) uses the pseudo-inverse.
double kinetic_energy(const RigidBody& body);

// The body-axes inverse inertia's principal axes and eigenvalues: fixed for a body, so a caller that needs the
// kinetic energy of the same bodies every frame (the world's step report) finds them once.
struct PrincipalInertia {
    Mat3 axes = Mat3::Identity();         // columns: the principal axes, body coordinates
    Vec3 inverse_moments = Vec3::Zero();  // the inverse inertia's eigenvalues, along those axes
};
PrincipalInertia principal_inertia(const RigidBody& body);
double kinetic_energy(const RigidBody& body, const PrincipalInertia& principal);

}  // namespace impulse
