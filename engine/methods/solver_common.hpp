#pragma once
// What the methods share (solver2d's solver.c): the book's impulse for one contact (steps 6 and 7 on its
// bookkeeping), with K and its factors kept per contact for the frame, applying a velocity change to the bodies, and
// the contact memory's end of frame for the methods that own the whole step.

#include "body/rigid_body.hpp"
#include "methods/method.hpp"
#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "preparation/bookkeeping.hpp"
#include "preparation/prepared_contact.hpp"
#include "record/iteration_records.hpp"
#include "settings/settings.hpp"

#include <array>
#include <memory_resource>
#include <span>
#include <vector>

namespace impulse {

// K and its factors for the book's friction impulse, per contact: computed by the first impulse on the contact
// and reused by the later ones, since they depend only on what preparation fixed (a frame of a resting grid
// resolves half of its contacts, so they are not computed for every contact up front).
class FrictionMatrices {
public:
    FrictionMatrices(std::size_t contact_count, std::pmr::memory_resource* scratch);
    const FactoredDeltaVelocityMatrix& of(const PreparedContact& contact, std::span<const MassProperties> mass);

private:
    std::pmr::vector<int> slot_;  // per contact: its place in matrices_, or -1
    std::pmr::vector<FactoredDeltaVelocityMatrix> matrices_;
};

// Steps 6 and 7 for one contact, on its bookkeeping velocity and desired delta v (step 5, with the Baumgarte
// term when it is on), the sliding impulse as settings.sliding_friction says: worst-first and the sequential sweep
// both visit a contact this way.
VelocityResolution resolve_velocity(const PreparedContact& contact, std::span<const MassProperties> mass,
                                    FrictionMatrices& k, const ResolverSettings& settings);

// Adds step 7's velocity_change and rotation_change to the contact's bodies (the world never changes).
void apply_velocity_change(std::vector<RigidBody>& bodies, const std::array<int, 2>& changed,
                           const VelocityChange& change);

// One visit of the book's velocity methods to contact `chosen`: its impulse (resolve_velocity), stamped, reported
// when the recorder keeps the frame (at `sweep`, none for worst first) and applied to its bodies. The caller then
// updates the bookkeeping of the contacts sharing a body (update_contact_velocities) with its step 7. Inline, so each
// method's loop compiles as it did when it wrote the visit out.
inline VelocityResolution visit_contact(FrameContext& frame, FrictionMatrices& k, int chosen,
                                        std::optional<SweepPlace> sweep) {
    const PreparedContact& contact = frame.contacts[static_cast<std::size_t>(chosen)];
    const VelocityResolution resolution = resolve_velocity(contact, frame.mass, k, frame.settings);
    frame.touched(chosen);
    if (frame.keeping)
        frame.recorder.velocity_visit({.contact = chosen,
                                       .sweep = sweep,
                                       .epsilon = frame.settings.velocity_epsilon,
                                       .updates = DesiredFollows::step_5,
                                       .resolution = &resolution});
    apply_velocity_change(frame.bodies, contact.bodies, resolution.velocity_change_terms);
    return resolution;
}

// A method that owns the whole step (soft step, AVBD) runs its Step; then what it accumulated is kept in the
// contact memory for the next frame when warm starting, or the memory emptied, so that warm starting switched on
// later starts from nothing rather than from totals of frames ago. Every visit counts as an iteration.
template <typename Step>
PhaseOutcome whole_step(FrameContext& frame) {
    Step step(frame);
    step.run();
    if (frame.memory && frame.settings.warm_start)
        step.remember(*frame.memory);
    else if (frame.memory)
        frame.memory->clear();
    return {step.visit_limit(), step.visits(), StopReason::sweeps_complete};
}

}  // namespace impulse
