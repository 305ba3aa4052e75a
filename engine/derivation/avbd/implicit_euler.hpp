#pragma once
// AVBD's time step at its two ends. AVBD (Giles, Diaz and Yuksel 2025, after Chen et al.'s VBD 2024) solves
// implicit Euler in its variational form,
//   x+ = argmin_x G(x),   G(x) = 1/(2h^2) |x - y|^2_M + E(x),
// where E is the contacts' energy and y the inertial target (Eq. 2): where each body would be at the end of the
// frame if nothing touched it. The iterations move the bodies; at the end each body's velocity is read off how
// far it moved (BDF1, backward Euler). A rigid body's x is its centre and its orientation; the iterations work
// on its displacement since the frame began, a translation and a rotation vector (Sec. 4 linearises rotations
// at the frame's start, as the chapter's rotation_change does).

#include "body/integrate.hpp"
#include "body/rigid_body.hpp"

namespace impulse {

// A body's move since the frame began: translation and rotation vector (axis x angle), world.
struct Displacement {
    Vec3 linear = Vec3::Zero();   // m
    Vec3 angular = Vec3::Zero();  // rad

    bool operator==(const Displacement&) const = default;
};

struct InertialTarget {
    // y - x-: h v' and h w', where v' = (v + g h) damped and w' = w damped, exactly as the world's integration
    // takes a free body through a frame (body/integrate.hpp), so a body that touches nothing moves as it would
    // under every other method. Without damping, y = x + h v + h^2 g  (Eq. 2).
    Displacement inertial_target;
    // VBD's adaptive initialisation: how much of gravity last frame's acceleration showed along g, clamped to
    // [0, 1]. A falling body (a = g) starts at y; a resting one (a = 0) starts where its velocity takes it.
    double acceleration_weight = 0.0;
    Displacement initial_guess;  // where the iterations start: y - (1 - a~) h^2 g
};

InertialTarget inertial_target(const RigidBody& body, const Vec3& gravity, double h, const Damping& damping);

struct Bdf1Velocity {
    Vec3 velocity;          // v+ = delta p / h
    Vec3 angular_velocity;  // w+ = delta theta / h
    Vec3 acceleration;      // (v+ - v-) / h: the frame's acceleration, which the next frame's initial guess reads
};

// The velocities the frame's displacement implies (BDF1: the backward difference over one frame).
Bdf1Velocity velocity_from_displacement(const RigidBody& before, const Displacement& moved, double h);

}  // namespace impulse
