#include "methods/position_resolution.hpp"
#include "resolver/bookkeeping.hpp"
#include "resolver/phases.hpp"

#include <algorithm>

namespace impulse {

namespace {

double penetration_of(const PreparedContact& c) {
    return c.penetration;
}

PositionResolution projection_for(const PreparedContact& contact, double amount, std::span<const RigidBody> bodies,
                                  const PositionPhaseState& state, const ResolverSettings& settings) {
    switch (settings.position_method) {
        case PositionMethod::linear_projection:
            return linear_projection(contact, amount);
        case PositionMethod::velocity_based: {
            PerBody<BodyMotion> motion;
            double time_left = settings.duration;
            for (int i = 0; i < 2; ++i) {
                const int id = contact.derivation.bodies[i];
                if (id == world_body) continue;
                const RigidBody& body = bodies[static_cast<std::size_t>(id)];
                motion[i] = BodyMotion{body.velocity, body.angular_velocity, body.last_frame_acceleration};
                time_left = std::min(time_left, settings.duration - state.rewound_time[static_cast<std::size_t>(id)]);
            }
            return velocity_based(contact, motion, time_left, settings.angular_limit, settings.orientation_update);
        }
        case PositionMethod::baumgarte:
        case PositionMethod::split_impulse:  // velocity-level methods: never projected (resolve_positions)
        case PositionMethod::nonlinear_projection:
        case PositionMethod::relaxation: {
            PositionResolution r =
                nonlinear_projection(contact, amount, settings.angular_limit, settings.orientation_update);
            r.method = settings.position_method;
            return r;
        }
    }
    return linear_projection(contact, amount);
}

}  // namespace

WorstFirstSelector penetration_selector(const std::vector<PreparedContact>& contacts, std::size_t body_count,
                                        const ResolverSettings& settings) {
    std::vector<char> eligible(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i)
        eligible[i] = !contacts[i].derivation.inert && movable_by(settings.position_method, contacts[i]);
    return WorstFirstSelector(settings.worst_first_search, contacts, body_count, penetration_of, std::move(eligible));
}

bool any_penetration_above(const std::vector<PreparedContact>& contacts, double epsilon) {
    return std::any_of(contacts.begin(), contacts.end(),
                       [epsilon](const PreparedContact& c) { return !c.derivation.inert && c.penetration > epsilon; });
}

PositionPhaseState position_phase_state(std::size_t body_count) {
    return {std::vector<double>(body_count, 0.0)};
}

bool movable_by(PositionMethod method, const PreparedContact& contact) {
    if (method != PositionMethod::linear_projection) return true;
    for (const auto& m : contact.mass)
        if (m && m->inverse_mass > 0.0) return true;
    return false;
}

void resolve_penetration(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                         PositionPhaseState& state, WorstFirstSelector& selector, int chosen, double amount,
                         int iteration, std::optional<int> pass, const ResolverSettings& settings, Recorder& recorder) {
    const PreparedContact& contact = contacts[static_cast<std::size_t>(chosen)];
    PositionIteration record{iteration,
                             chosen,
                             contact.penetration,
                             settings.position_epsilon,
                             pass,
                             projection_for(contact, amount, bodies, state, settings),
                             {}};
    const std::array<int, 2> moved = contact.derivation.bodies;
    const PositionChange& change = record.resolution->change;
    for (int i = 0; i < 2; ++i) {
        if (moved[i] == world_body) continue;
        if (record.resolution->rewind)
            state.rewound_time[static_cast<std::size_t>(moved[i])] += record.resolution->rewind->time;
        RigidBody& body = bodies[static_cast<std::size_t>(moved[i])];
        body.position += *change.linear_change[i];
        body.orientation = rotated(body.orientation, *change.angular_change[i], settings.orientation_update);
    }
    const std::span<const int> sharing = selector.sharing(moved);
    update_penetrations(contacts, sharing, moved, change, recorder.wants_updates() ? &record.updates : nullptr);
    selector.values_changed(sharing);
    recorder.position_iteration(record);
}

PhaseOutcome resolve_positions(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                               const ResolverSettings& settings, Recorder& recorder) {
    switch (settings.position_method) {
        case PositionMethod::relaxation:
            return relax_positions(bodies, contacts, settings, recorder);
        case PositionMethod::baumgarte:
            return baumgarte_positions(settings, recorder);
        case PositionMethod::split_impulse:
            return split_impulse_positions(bodies, contacts, settings, recorder);
        case PositionMethod::linear_projection:
        case PositionMethod::nonlinear_projection:
        case PositionMethod::velocity_based:
            break;
    }

    PhaseOutcome outcome;
    outcome.iteration_limit = position_iteration_limit(settings, static_cast<int>(contacts.size()));
    PositionPhaseState state = position_phase_state(bodies.size());
    WorstFirstSelector selector = penetration_selector(contacts, bodies.size(), settings);
    while (outcome.iterations_used < outcome.iteration_limit) {
        const std::optional<int> chosen = selector.worst(settings.position_epsilon);
        if (!chosen) break;
        const double penetration = contacts[static_cast<std::size_t>(*chosen)].penetration;
        resolve_penetration(bodies, contacts, state, selector, *chosen, penetration, outcome.iterations_used,
                            std::nullopt, settings, recorder);
        ++outcome.iterations_used;
    }
    outcome.stop = selector.worst(settings.position_epsilon)                    ? StopReason::iteration_limit
                   : any_penetration_above(contacts, settings.position_epsilon) ? StopReason::unmovable_left
                                                                                : StopReason::resolved;
    recorder.end_phase(Phase::position, outcome);
    return outcome;
}

}  // namespace impulse
