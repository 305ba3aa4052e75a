// The sequential sweep: the book's impulse for one contact at a time (steps 6 and 7 on the contact's current
// velocity and desired delta v), but contacts are visited in index order instead of worst first, `sweeps`
// times. Each visit is exactly a worst-first iteration; only the choice of the next contact differs, so the
// two methods can be compared on the cost of finding the worst contact against the order's effect on
// accuracy. As in the book, a contact whose desired delta v is at or below the velocity epsilon is skipped,
// and each impulse updates the bookkeeping of every contact sharing a body (the linearised formulas of
// preparation/bookkeeping.hpp). The sweeps stop early when a whole sweep found nothing to resolve.
//
// Each impulse makes its own contact's normal velocity exactly its target and nothing else holds the total:
// a later contact's impulse may undo it, and no impulse is ever taken back. On a stack the sweep therefore
// converges like Gauss-Seidel on the book's unclamped system, but cannot remove an impulse that turned out
// too large (projected Gauss-Seidel can: methods/projected_gauss_seidel.cpp).
//
// Reported: every visit with sweep = {0, pass, solve} and the book's values; the iteration limit is
// sweeps x contacts (iterations_per_contact and velocity_iterations do not apply).

#include "methods/solver_common.hpp"
#include "methods/phases.hpp"
#include "preparation/bookkeeping.hpp"

#include <algorithm>

namespace impulse {

PhaseOutcome sequential_sweep_velocities(FrameContext& frame) {
    std::span<PreparedContact> contacts = frame.contacts;
    const ResolverSettings& settings = frame.settings;
    PhaseOutcome outcome;
    outcome.iteration_limit = std::max(settings.sweeps, 0) * static_cast<int>(contacts.size());
    const ContactsByBody by_body(contacts, frame.bodies.size());  // so a visit updates its neighbours only
    std::vector<int> sharing;
    FrictionMatrices k(contacts.size(), frame.scratch);
    const VelocityRefinements refinements = velocity_refinements(settings);
    for (int pass = 0; pass < settings.sweeps; ++pass) {
        if (frame.stop_requested()) break;
        bool resolved_any = false;
        for (int i = 0; i < static_cast<int>(contacts.size()); ++i) {
            const PreparedContact& contact = contacts[static_cast<std::size_t>(i)];
            if (contact.inert || desired_of(contact) <= settings.velocity_epsilon) continue;
            const VelocityResolution visit = visit_contact(frame, k, i, SweepPlace{0, pass, SolverStage::solve});
            const std::array<int, 2> changed = contact.bodies;
            by_body.sharing(changed, sharing);
            update_contact_velocities(contacts, sharing, changed, visit.velocity_change_terms, refinements);
            ++outcome.iterations_used;
            resolved_any = true;
        }
        if (!resolved_any) break;
    }
    outcome.stop =
        any_above(contacts, settings.velocity_epsilon, desired_of) ? StopReason::sweeps_complete : StopReason::resolved;
    return outcome;
}

}  // namespace impulse
