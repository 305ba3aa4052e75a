// Worst first, the book's velocity phase: "we find the contact with the largest closing velocity and resolve
// it", then update the contact velocity and desired delta v of every contact that shares a body with it (the
// linearised formulas of methods/bookkeeping.cpp), and repeat until no desired delta v is above the epsilon
// or the iteration limit is reached. Each impulse is the book's (steps 6 and 7 on the contact's bookkeeping
// velocity and desired delta v, methods/solver_common.hpp), final: nothing takes it back.

#include "methods/solver_common.hpp"
#include "methods/bookkeeping.hpp"
#include "methods/phases.hpp"

namespace impulse {

PhaseOutcome worst_first_velocities(FrameContext& frame) {
    std::vector<RigidBody>& bodies = frame.bodies;
    std::vector<PreparedContact>& contacts = frame.contacts;
    const ResolverSettings& settings = frame.settings;
    Recorder& recorder = frame.recorder;
    PhaseOutcome outcome;
    outcome.iteration_limit = velocity_iteration_limit(settings, static_cast<int>(contacts.size()));
    std::vector<char> eligible(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i) eligible[i] = !contacts[i].derivation.inert;
    WorstFirstSelector selector(settings.worst_first_search, contacts, bodies.size(), desired_of, std::move(eligible));
    while (outcome.iterations_used < outcome.iteration_limit) {
        if (outcome.iterations_used % stop_check_visits == 0 && frame.stop_requested()) break;
        const std::optional<int> chosen = selector.worst(settings.velocity_epsilon);
        if (!chosen) break;
        const PreparedContact& contact = contacts[static_cast<std::size_t>(*chosen)];
        VelocityIteration record{.iteration = outcome.iterations_used,
                                 .contact = *chosen,
                                 .desired_delta_velocity = desired_of(contact),
                                 .epsilon = settings.velocity_epsilon,
                                 .sweep = {},
                                 .accumulated = {},
                                 .resolution = resolve_velocity(contact, settings.sliding_friction),
                                 .updates = {}};
        const std::array<int, 2> changed = contact.derivation.bodies;
        const VelocityChange& change = record.resolution->velocity_change_terms;
        apply_velocity_change(bodies, changed, change);
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
