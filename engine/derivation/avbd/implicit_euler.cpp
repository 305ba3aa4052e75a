#include "derivation/avbd/implicit_euler.hpp"

#include <algorithm>
#include <cmath>

namespace impulse {

InertialTarget inertial_target(const RigidBody& body, const Vec3& gravity, double h, const Damping& damping) {
    // The free velocity after the frame, by the world's own integration of velocities (gravity, then damping).
    RigidBody free = body;
    integrate_velocity(free, gravity, h, damping);
    InertialTarget t;
    t.inertial_target = {free.velocity * h, free.angular_velocity * h};  // y - x-  (Eq. 2)
    // a~ = clamp(a . g / |g|^2, 0, 1), a = last frame's acceleration (VBD's adaptive initialisation, Chen et al. 2024).
    const double g2 = gravity.squaredNorm();
    const double weight = g2 > 0.0 ? body.last_frame_acceleration.dot(gravity) / g2 : 0.0;
    t.acceleration_weight = std::isfinite(weight) ? std::clamp(weight, 0.0, 1.0) : 0.0;
    const Vec3 gravity_share = body.inverse_mass > 0.0 ? Vec3(gravity * (h * h)) : Vec3(Vec3::Zero());
    t.initial_guess = {t.inertial_target.linear - (1.0 - t.acceleration_weight) * gravity_share,
                       t.inertial_target.angular};
    return t;
}

Bdf1Velocity velocity_from_displacement(const RigidBody& before, const Displacement& moved, double h) {
    const Vec3 velocity = moved.linear / h;
    return {velocity, moved.angular / h, (velocity - before.velocity) / h};
}

}  // namespace impulse
