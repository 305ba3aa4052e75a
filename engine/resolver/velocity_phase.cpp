#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "resolver/bookkeeping.hpp"
#include "resolver/phases.hpp"

namespace impulse {

namespace {

double desired_of(const PreparedContact& c) {
    return c.desired_delta_velocity.desired_delta_velocity;
}

// Steps 6 and 7 for the chosen contact, on its current (partly resolved) velocity.
VelocityResolution resolve_velocity(const PreparedContact& contact) {
    const ContactPreparation& d = contact.derivation;
    VelocityResolution r;
    r.contact_velocity = contact.contact_velocity;
    r.desired_delta_velocity = contact.desired_delta_velocity;
    r.impulse = calculate_impulse(d.basis, d.relative_position, contact.mass, contact.contact_velocity,
                                  contact.desired_delta_velocity.desired_delta_velocity,
                                  d.velocity_per_unit_impulse.delta_velocity_per_unit_impulse, d.friction);
    r.velocity_change = velocity_change(r.impulse.impulse_world, d.relative_position, contact.mass);
    return r;
}

}  // namespace

PhaseOutcome resolve_velocities(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                                const ResolverSettings& settings, Recorder& recorder) {
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
