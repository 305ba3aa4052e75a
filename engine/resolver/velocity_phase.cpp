#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "methods/solver_common.hpp"
#include "resolver/bookkeeping.hpp"
#include "resolver/phases.hpp"

namespace impulse {

namespace {

double desired_of(const PreparedContact& c) {
    return c.desired_delta_velocity.desired_delta_velocity;
}

}  // namespace

PhaseOutcome resolve_velocities(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                                const ResolverSettings& settings, Recorder& recorder, ContactMemory* memory) {
    switch (settings.velocity_method) {
        case VelocityMethod::sequential_sweep:
            return sweep_velocities(bodies, contacts, settings, recorder);
        case VelocityMethod::projected_gauss_seidel:
            return pgs_velocities(bodies, contacts, settings, recorder, memory);
        case VelocityMethod::soft_step:  // soft_step never reaches here: resolve_contacts hands it to soft_step()
        case VelocityMethod::worst_first:
            break;
    }
    PhaseOutcome outcome;
    outcome.iteration_limit = velocity_iteration_limit(settings, static_cast<int>(contacts.size()));
    while (outcome.iterations_used < outcome.iteration_limit) {
        const std::optional<int> chosen = worst_contact(contacts, desired_of, settings.velocity_epsilon);
        if (!chosen) break;
        const PreparedContact& contact = contacts[static_cast<std::size_t>(*chosen)];
        VelocityIteration record{.iteration = outcome.iterations_used,
                                 .contact = *chosen,
                                 .desired_delta_velocity = desired_of(contact),
                                 .epsilon = settings.velocity_epsilon,
                                 .sweep = {},
                                 .accumulated = {},
                                 .resolution = resolve_velocity(contact),
                                 .updates = {}};
        const std::array<int, 2> changed = contact.derivation.bodies;
        const VelocityChange& change = record.resolution->velocity_change;
        for (int i = 0; i < 2; ++i) {
            if (changed[i] == world_body) continue;
            RigidBody& body = bodies[static_cast<std::size_t>(changed[i])];
            body.velocity += *change.velocity_change[i];
            body.angular_velocity += *change.rotation_change[i];
        }
        update_contact_velocities(contacts, changed, change, settings,
                                  recorder.wants_updates() ? &record.updates : nullptr);
        recorder.velocity_iteration(record);
        ++outcome.iterations_used;
    }
    outcome.stop =
        any_above(contacts, desired_of, settings.velocity_epsilon) ? StopReason::iteration_limit : StopReason::resolved;
    recorder.end_phase(Phase::velocity, outcome);
    return outcome;
}

}  // namespace impulse
