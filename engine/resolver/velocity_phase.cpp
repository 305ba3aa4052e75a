#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "methods/solver_common.hpp"
#include "resolver/bookkeeping.hpp"
#include "resolver/phases.hpp"

#include <algorithm>

namespace impulse {

bool any_desired_delta_velocity_above(const std::vector<PreparedContact>& contacts, double epsilon) {
    return std::any_of(contacts.begin(), contacts.end(), [epsilon](const PreparedContact& c) {
        return !c.derivation.inert && desired_of(c) > epsilon;
    });
}

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
    std::vector<char> eligible(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i) eligible[i] = !contacts[i].derivation.inert;
    WorstFirstSelector selector(settings.worst_first_search, contacts, bodies.size(), desired_of, std::move(eligible));
    while (outcome.iterations_used < outcome.iteration_limit) {
        const std::optional<int> chosen = selector.worst(settings.velocity_epsilon);
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
        const std::span<const int> sharing = selector.sharing(changed);
        update_contact_velocities(contacts, sharing, changed, change, settings,
                                  recorder.wants_updates() ? &record.updates : nullptr);
        selector.values_changed(sharing);
        recorder.velocity_iteration(record);
        ++outcome.iterations_used;
    }
    outcome.stop = selector.worst(settings.velocity_epsilon) ? StopReason::iteration_limit : StopReason::resolved;
    recorder.end_phase(Phase::velocity, outcome);
    return outcome;
}

}  // namespace impulse
