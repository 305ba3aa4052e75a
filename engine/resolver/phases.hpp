#pragma once
// The two phases of resolution, each a worst-first loop (the book's): pick the contact whose value is
// largest above the epsilon, resolve it alone, update every contact that shares a body, repeat until
// nothing is above the epsilon or the iteration limit is reached.

#include "body/rigid_body.hpp"
#include "record/recorder.hpp"
#include "resolver/prepared_contact.hpp"
#include "resolver/settings.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace impulse {

// The index of the contact with the largest value strictly above `epsilon`, skipping inert contacts and
// those `skip` rejects; the first index wins a tie, as in the reference engine.
std::optional<int> worst_contact(const std::vector<PreparedContact>& contacts,
                                 const std::function<double(const PreparedContact&)>& value, double epsilon,
                                 const std::function<bool(int)>& skip = {});

// Removes `amount` of contact `chosen`'s penetration with the configured method, moves its bodies, updates
// the penetration of every contact sharing them, and reports the iteration.
void resolve_penetration(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts, int chosen,
                         double amount, int iteration, std::optional<int> pass, const ResolverSettings& settings,
                         Recorder& recorder);

PhaseOutcome resolve_positions(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                               const ResolverSettings& settings, Recorder& recorder);

// Relaxation's position phase (methods/relaxation.cpp): passes instead of one worst-first run.
PhaseOutcome relax_positions(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                             const ResolverSettings& settings, Recorder& recorder);

PhaseOutcome resolve_velocities(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                                const ResolverSettings& settings, Recorder& recorder);

// Whether any contact is still above the epsilon (used to tell "resolved" from "iteration limit").
bool any_above(const std::vector<PreparedContact>& contacts, const std::function<double(const PreparedContact&)>& value,
               double epsilon);

}  // namespace impulse
