#include "methods/phases.hpp"
#include "preparation/bookkeeping.hpp"

namespace impulse {

WorstFirstSelector penetration_selector(const FrameContext& frame, Movable movable) {
    const std::span<const PreparedContact> contacts = frame.contacts;
    std::vector<char> eligible(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i)
        eligible[i] = !contacts[i].inert && (!movable || movable(contacts[i], frame.mass));
    return WorstFirstSelector(frame.settings.worst_first_search, contacts, frame.bodies.size(), penetration_of,
                              std::move(eligible));
}

void resolve_penetration(FrameContext& frame, Projection projection, PositionPhaseState& state,
                         WorstFirstSelector& selector, int chosen, double amount, std::optional<int> pass) {
    const ResolverSettings& settings = frame.settings;
    const PreparedContact& contact = frame.contacts[static_cast<std::size_t>(chosen)];
    const PositionResolution resolution = projection(contact, amount, state, frame);
    frame.touched(chosen);
    if (frame.keeping)
        frame.recorder.position_visit(
            {.contact = chosen, .pass = pass, .resolution = &resolution, .epsilon = settings.position_epsilon});
    const std::array<int, 2> moved = contact.bodies;
    const PositionChange& change = resolution.change;
    for (int i = 0; i < 2; ++i) {
        if (moved[i] == world_body) continue;
        if (resolution.rewind) state.rewound_time[static_cast<std::size_t>(moved[i])] += resolution.rewind->time;
        RigidBody& body = frame.bodies[static_cast<std::size_t>(moved[i])];
        body.position += *change.linear_change[i];
        body.orientation = rotated(body.orientation, *change.angular_change[i], settings.orientation_update);
    }
    const std::span<const int> sharing = selector.sharing(moved);
    update_penetrations(frame.contacts, sharing, moved, change);
    selector.values_changed(sharing);
}

PhaseOutcome worst_first_positions(FrameContext& frame, Projection projection, Movable movable) {
    const ResolverSettings& settings = frame.settings;
    PhaseOutcome outcome;
    outcome.iteration_limit =
        iteration_limit(settings.position_iterations, settings, static_cast<int>(frame.contacts.size()));
    PositionPhaseState state{std::vector<double>(frame.bodies.size(), 0.0)};
    WorstFirstSelector selector = penetration_selector(frame, movable);
    while (outcome.iterations_used < outcome.iteration_limit) {
        if (outcome.iterations_used % stop_check_visits == 0 && frame.stop_requested()) break;
        const std::optional<int> chosen = selector.worst(settings.position_epsilon);
        if (!chosen) break;
        const double penetration = frame.contacts[static_cast<std::size_t>(*chosen)].penetration;
        resolve_penetration(frame, projection, state, selector, *chosen, penetration, std::nullopt);
        ++outcome.iterations_used;
    }
    outcome.stop = selector.worst(settings.position_epsilon)                              ? StopReason::iteration_limit
                   : any_above(frame.contacts, settings.position_epsilon, penetration_of) ? StopReason::unmovable_left
                                                                                          : StopReason::resolved;
    return outcome;
}

}  // namespace impulse
