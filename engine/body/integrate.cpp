#include "body/integrate.hpp"

#include "math/elementary.hpp"

namespace impulse {

void integrate(RigidBody& body, const Vec3& gravity, double dt, const Damping& damping, OrientationUpdate update) {
    integrate_velocity(body, gravity, dt, damping);
    integrate_position(body, dt, update);
}

void integrate_velocity(RigidBody& body, const Vec3& gravity, double dt, const Damping& damping) {
    body.last_frame_acceleration = body.inverse_mass > 0.0 ? gravity : Vec3::Zero();
    body.velocity += body.last_frame_acceleration * dt;
    // No torque acts (gravity pulls through the centre of mass), so I^-1 tau dt adds nothing to w.
    // Damping slows what can be slowed: an immovable body keeps the motion it was given.
    if (damping.linear != 1.0 && body.inverse_mass > 0.0) body.velocity *= elementary::pow(damping.linear, dt);
    if (damping.angular != 1.0 && !body.inverse_inertia_body.isZero(0.0))
        body.angular_velocity *= elementary::pow(damping.angular, dt);
}

void integrate_position(RigidBody& body, double dt, OrientationUpdate update) {
    body.position += body.velocity * dt;
    body.orientation = rotated(body.orientation, body.angular_velocity * dt, update);
}

}  // namespace impulse
