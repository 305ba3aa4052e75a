#pragma once
// The two phases of resolution, each a worst-first loop (the book's): pick the contact whose value is
// largest above the epsilon, resolve it alone, update every contact that shares a body, repeat until
// nothing is above the epsilon or the iteration limit is reached.

#include "body/rigid_body.hpp"
#include "memory/contact_memory.hpp"
#include "record/recorder.hpp"
#include "resolver/prepared_contact.hpp"
#include "resolver/settings.hpp"
#include "resolver/worst_first_selector.hpp"

#include <optional>
#include <vector>

namespace impulse {

// The phase's chooser (worst_first_selector.hpp): every non-inert contact, by the value the phase compares.
WorstFirstSelector penetration_selector(const std::vector<PreparedContact>& contacts, std::size_t body_count,
                                        const ResolverSettings& settings);

// Whether any non-inert contact is still above the epsilon (tells "resolved" from the other stop reasons);
// one scan, once per phase.
bool any_penetration_above(const std::vector<PreparedContact>& contacts, double epsilon);
bool any_desired_delta_velocity_above(const std::vector<PreparedContact>& contacts, double epsilon);

// What the position phase carries from one iteration to the next besides the contacts.
struct PositionPhaseState {
    std::vector<double> rewound_time;  // per body: how far velocity-based resolution moved it back this frame (s)
};

PositionPhaseState position_phase_state(std::size_t body_count);

// Whether the configured method can move this contact at all: linear projection cannot move a contact whose
// bodies cannot translate, and choosing it again would only spend iterations.
bool movable_by(PositionMethod method, const PreparedContact& contact);

// Removes `amount` of contact `chosen`'s penetration with the configured method, moves its bodies, updates
// the penetration of every contact sharing them (telling `selector`), and reports the iteration.
void resolve_penetration(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                         PositionPhaseState& state, WorstFirstSelector& selector, int chosen, double amount,
                         int iteration, std::optional<int> pass, const ResolverSettings& settings, Recorder& recorder);

PhaseOutcome resolve_positions(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                               const ResolverSettings& settings, Recorder& recorder);

// Relaxation's position phase (methods/relaxation.cpp): passes instead of one worst-first run.
PhaseOutcome relax_positions(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                             const ResolverSettings& settings, Recorder& recorder);

// Baumgarte's position phase (methods/baumgarte.cpp): nothing to move, the bias is in the velocity targets.
PhaseOutcome baumgarte_positions(const ResolverSettings& settings, Recorder& recorder);

// The split impulse's position phase (methods/split_impulse.cpp): a push solve on pseudo-velocities.
PhaseOutcome split_impulse_positions(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                                     const ResolverSettings& settings, Recorder& recorder);

// The velocity phase of the configured method; `memory` carries projected Gauss-Seidel's totals between frames.
PhaseOutcome resolve_velocities(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                                const ResolverSettings& settings, Recorder& recorder, ContactMemory* memory = nullptr);

// The sequential sweep's velocity phase (methods/sequential_sweep.cpp).
PhaseOutcome sweep_velocities(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                              const ResolverSettings& settings, Recorder& recorder);

// Projected Gauss-Seidel's velocity phase (methods/projected_gauss_seidel.cpp).
PhaseOutcome pgs_velocities(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                            const ResolverSettings& settings, Recorder& recorder, ContactMemory* memory);

}  // namespace impulse
