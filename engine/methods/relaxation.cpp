// Relaxation: "resolves only a proportion of the interpenetration at one go ... Each gets to resolve a
// little, and then the others take their turns. This typically is repeated several times." Each pass
// visits every contact still above the epsilon once, deepest first at the moment of choosing, and removes
// `fraction` of its current penetration by nonlinear projection. Contacts that fight over one body (a
// brick in a wall) then share the remaining penetration instead of one of them keeping all of it; the
// price is that an isolated contact keeps (1 - fraction)^passes of its penetration.

#include "methods/phases.hpp"

#include <algorithm>
#include <vector>

namespace impulse {

namespace {

PositionResolution project(const PreparedContact& contact, double amount, const PositionPhaseState& /*state*/,
                           const FrameContext& frame) {
    PositionResolution r = nonlinear_projection(contact, mass_of(contact, frame.mass), amount,
                                                frame.settings.angular_limit, frame.settings.orientation_update);
    r.method = PositionMethod::relaxation;
    return r;
}

}  // namespace

PhaseOutcome relaxation_positions(FrameContext& frame) {
    const ResolverSettings& settings = frame.settings;
    std::span<PreparedContact> contacts = frame.contacts;
    PhaseOutcome outcome;
    outcome.iteration_limit =
        iteration_limit(settings.position_iterations, settings, static_cast<int>(contacts.size()));
    PositionPhaseState state{std::vector<double>(frame.bodies.size(), 0.0)};
    WorstFirstSelector selector = penetration_selector(frame, nullptr);
    bool cut_short = false;  // the iteration limit stopped a pass with a contact still waiting for its turn
    for (int pass = 0; pass < settings.relaxation.passes && !cut_short && !frame.cut_short; ++pass) {
        if (!any_above(contacts, settings.position_epsilon, penetration_of)) break;
        if (pass > 0) selector.restart();  // every contact gets a turn again
        while (const std::optional<int> chosen = selector.worst(settings.position_epsilon)) {
            if (outcome.iterations_used == outcome.iteration_limit) {
                cut_short = true;
                break;
            }
            if (outcome.iterations_used % stop_check_visits == 0 && frame.stop_requested()) break;
            selector.set_aside(*chosen);  // one visit per pass
            const double amount =
                settings.relaxation.fraction * contacts[static_cast<std::size_t>(*chosen)].penetration;
            resolve_penetration(frame, project, state, selector, *chosen, amount, pass);
            ++outcome.iterations_used;
        }
    }
    // Relaxation leaves penetration by design; the stop reason says whether any is left above the epsilon,
    // and whether the iteration limit cut the passes short.
    const bool remaining = any_above(contacts, settings.position_epsilon, penetration_of);
    outcome.stop = !remaining  ? StopReason::resolved
                   : cut_short ? StopReason::iteration_limit
                               : StopReason::passes_complete;
    return outcome;
}

}  // namespace impulse
