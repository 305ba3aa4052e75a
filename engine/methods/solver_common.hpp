#pragma once
// What the velocity methods share (solver2d's solver.c): the book's impulse for one contact (steps 6 and 7
// on its current velocity), applying a velocity change to the bodies, the contact velocity read from the
// bodies as they are now, and a prepared contact's identity across frames.

#include "body/rigid_body.hpp"
#include "derivation/velocity_change.hpp"
#include "memory/contact_memory.hpp"
#include "record/iteration_records.hpp"
#include "preparation/prepared_contact.hpp"
#include "settings/settings.hpp"

#include <array>
#include <span>
#include <utility>
#include <vector>

namespace impulse {

// Steps 6 and 7 for one contact, on its bookkeeping velocity and desired delta v (step 5, with the Baumgarte
// term when it is on), the sliding impulse as `sliding` says: worst-first and the sequential sweep both visit
// a contact this way.
VelocityResolution resolve_velocity(const PreparedContact& contact, SlidingFriction sliding);

// Adds step 7's velocity_change and rotation_change to the contact's bodies (the world never changes).
void apply_velocity_change(std::vector<RigidBody>& bodies, const std::array<int, 2>& changed,
                           const VelocityChange& change);

// Step 4 on the bodies' velocities as they are now, not on the linearised bookkeeping: sequential impulses
// read the velocity afresh at every visit, so rounding never accumulates in a copy.
Vec3 current_contact_velocity(const PreparedContact& contact, std::span<const RigidBody> bodies,
                              const ResolverSettings& settings);

// The key the contact had as detected (before preparation put the world second), for ContactMemory.
template <typename Prepared>  // ContactPreparation or RowPreparation
ContactKey contact_key(const Prepared& contact) {
    ContactKey key{contact.bodies, contact.origin};
    if (contact.swapped) {
        std::swap(key.bodies[0], key.bodies[1]);
        std::swap(key.origin.features[0], key.origin.features[1]);
    }
    return key;
}

}  // namespace impulse
