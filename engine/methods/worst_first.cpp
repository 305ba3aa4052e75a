// Worst first, the book's velocity phase: "we find the contact with the largest closing velocity and resolve
// it", then update the contact velocity and desired delta v of every contact that shares a body with it (the
// linearised formulas of preparation/bookkeeping.hpp), and repeat until no desired delta v is above the epsilon
// or the iteration limit is reached. Each impulse is the book's (steps 6 and 7 on the contact's bookkeeping
// velocity and desired delta v, methods/solver_common.hpp), final: nothing takes it back.

#include "methods/solver_common.hpp"
#include "methods/phases.hpp"
#include "preparation/bookkeeping.hpp"

namespace impulse {

PhaseOutcome worst_first_velocities(FrameContext& frame) {
    std::span<PreparedContact> contacts = frame.contacts;
    const ResolverSettings& settings = frame.settings;
    PhaseOutcome outcome;
    outcome.iteration_limit =
        iteration_limit(settings.velocity_iterations, settings, static_cast<int>(contacts.size()));
    std::vector<char> eligible(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i) eligible[i] = !contacts[i].inert;
    WorstFirstSelector selector(settings.worst_first_search, contacts, frame.bodies.size(), desired_of,
                                std::move(eligible));
    FrictionMatrices k(contacts.size(), frame.scratch);
    const VelocityRefinements refinements = velocity_refinements(settings);
    while (outcome.iterations_used < outcome.iteration_limit) {
        if (outcome.iterations_used % stop_check_visits == 0 && frame.stop_requested()) break;
        const std::optional<int> chosen = selector.worst(settings.velocity_epsilon);
        if (!chosen) break;
        const VelocityResolution visit = visit_contact(frame, k, *chosen, std::nullopt);
        const std::array<int, 2> changed = contacts[static_cast<std::size_t>(*chosen)].bodies;
        const std::span<const int> sharing = selector.sharing(changed);
        update_contact_velocities(contacts, sharing, changed, visit.velocity_change_terms, refinements);
        selector.values_changed(sharing);
        ++outcome.iterations_used;
    }
    outcome.stop = selector.worst(settings.velocity_epsilon) ? StopReason::iteration_limit : StopReason::resolved;
    return outcome;
}

}  // namespace impulse
