#pragma once
// Semi-implicit (symplectic) Euler: the velocity is updated first and the position moves with the new
// velocity. The reference engine's integrator, used by its demo loop before contacts are generated.

#include "body/rigid_body.hpp"
#include "math/rotation.hpp"

namespace impulse {

struct Damping {
    double linear = 1.0;   // share of the velocity kept per second; 1 = none
    double angular = 1.0;  // likewise for angular velocity
};

// One step of dt under gravity (the only force; there are no torques):
//   a = g (kept as last_frame_acceleration for the resolver's chapter-15 refinements)
//   v += a dt,  w += I^-1 tau dt (= 0),  v *= d_lin^dt,  w *= d_ang^dt,
//   x += v dt,  q += 1/2 (0, w dt) q then normalise (or the exact update, as the settings say).
// An immovable body (inverse mass 0) feels no gravity and keeps its motion as given.
void integrate(RigidBody& body, const Vec3& gravity, double dt, const Damping& damping, OrientationUpdate update);

// The two halves of `integrate`, for a solver that works between them (soft step: velocities, then the contacts,
// then positions). integrate(...) is exactly integrate_velocity(...) followed by integrate_position(...).
void integrate_velocity(RigidBody& body, const Vec3& gravity, double dt, const Damping& damping);
void integrate_position(RigidBody& body, double dt, OrientationUpdate update);

}  // namespace impulse
