#pragma once
// Step 6 from a contact's record (relative positions and mass per body, empty for the world), K and its factors
// computed first, as the book's methods do where they read them (methods/solver_common.hpp).

#include "derivation/impulse.hpp"

namespace impulse {

inline Impulse calculate_impulse(const Basis& basis, const PerBody<Vec3>& relative_position,
                                 const PerBody<MassProperties>& mass, const Vec3& contact_velocity,
                                 double desired_delta_velocity, double delta_velocity_per_unit_impulse, double friction,
                                 SlidingFriction sliding = SlidingFriction::reference) {
    if (friction == 0.0)
        return calculate_impulse(basis, nullptr, contact_velocity, desired_delta_velocity,
                                 delta_velocity_per_unit_impulse, friction, sliding);
    std::array<Vec3, 2> q_rel{Vec3::Zero(), Vec3::Zero()};
    ContactMass m{nullptr, nullptr};
    for (int i = 0; i < 2; ++i)
        if (relative_position[i]) q_rel[i] = *relative_position[i], m[i] = &*mass[i];
    const FactoredDeltaVelocityMatrix k(delta_velocity_matrix(basis, q_rel, m));
    return calculate_impulse(basis, &k, contact_velocity, desired_delta_velocity, delta_velocity_per_unit_impulse,
                             friction, sliding);
}

}  // namespace impulse
