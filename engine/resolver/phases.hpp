#pragma once
// The two phases of resolution, each a worst-first loop (the book's): pick the contact whose value is
// largest above the epsilon, resolve it alone, update every contact that shares a body, repeat until
// nothing is above the epsilon or the iteration limit is reached.

#include "body/rigid_body.hpp"
#include "memory/contact_memory.hpp"
#include "record/recorder.hpp"
#include "resolver/prepared_contact.hpp"
#include "resolver/settings.hpp"

#include <optional>
#include <vector>

namespace impulse {

// The default for worst_contact: every contact may be chosen.
struct SkipNone {
    bool operator()(int) const { return false; }
};

// The index of the contact with the largest value(contact) strictly above `epsilon`, skipping inert contacts
// and those skip(index) rejects; the first index wins a tie, as in the reference engine. This scan over every
// contact is the book's own, and the resolver's cost per iteration.
template <typename Value, typename Skip = SkipNone>
std::optional<int> worst_contact(const std::vector<PreparedContact>& contacts, Value value, double epsilon,
                                 Skip skip = {}) {
    std::optional<int> worst;
    double largest = epsilon;
    for (int i = 0; i < static_cast<int>(contacts.size()); ++i) {
        const PreparedContact& c = contacts[static_cast<std::size_t>(i)];
        if (c.derivation.inert || skip(i)) continue;
        const double v = value(c);
        if (v > largest) {
            largest = v;
            worst = i;
        }
    }
    return worst;
}

// Whether any contact is still above the epsilon (tells "resolved" from "iteration limit").
template <typename Value>
bool any_above(const std::vector<PreparedContact>& contacts, Value value, double epsilon) {
    return worst_contact(contacts, value, epsilon).has_value();
}

// What the position phase carries from one iteration to the next besides the contacts.
struct PositionPhaseState {
    std::vector<double> rewound_time;  // per body: how far velocity-based resolution moved it back this frame (s)
};

PositionPhaseState position_phase_state(std::size_t body_count);

// Whether the configured method can move this contact at all: linear projection cannot move a contact whose
// bodies cannot translate, and choosing it again would only spend iterations.
bool movable_by(PositionMethod method, const PreparedContact& contact);

// Removes `amount` of contact `chosen`'s penetration with the configured method, moves its bodies, updates
// the penetration of every contact sharing them, and reports the iteration.
void resolve_penetration(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                         PositionPhaseState& state, int chosen, double amount, int iteration, std::optional<int> pass,
                         const ResolverSettings& settings, Recorder& recorder);

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

// Whether any contact is still above the epsilon (used to tell "resolved" from "iteration limit").
bool any_above(const std::vector<PreparedContact>& contacts, const std::function<double(const PreparedContact&)>& value,
               double epsilon);

}  // namespace impulse
