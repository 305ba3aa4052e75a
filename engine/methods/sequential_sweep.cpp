// The sequential sweep: the book's impulse for one contact at a time (steps 6 and 7 on the contact's current
// velocity and desired delta v), but contacts are visited in index order instead of worst first, `sweeps`
// times. Each visit is exactly a worst-first iteration; only the choice of the next contact differs, so the
// two methods can be compared on the cost of finding the worst contact against the order's effect on
// accuracy. As in the book, a contact whose desired delta v is at or below the velocity epsilon is skipped,
// and each impulse updates the bookkeeping of every contact sharing a body (the linearised formulas of
// methods/bookkeeping.cpp). The sweeps stop early when a whole sweep found nothing to resolve.
//
// Each impulse makes its own contact's normal velocity exactly its target and nothing else holds the total:
// a later contact's impulse may undo it, and no impulse is ever taken back. On a stack the sweep therefore
// converges like Gauss-Seidel on the book's unclamped system, but cannot remove an impulse that turned out
// too large (projected Gauss-Seidel can: methods/projected_gauss_seidel.cpp).
//
// Recorded: one VelocityIteration per visit with sweep = {0, pass, solve}, the book's derivation values and
// the bookkeeping updates; the iteration limit is sweeps x contacts (iterations_per_contact and
// velocity_iterations do not apply).

#include "methods/solver_common.hpp"
#include "methods/bookkeeping.hpp"
#include "methods/phases.hpp"

#include <algorithm>

namespace impulse {

namespace {

bool any_desired_delta_velocity_above(const std::vector<PreparedContact>& contacts, double epsilon) {
    return std::any_of(contacts.begin(), contacts.end(),
                       [epsilon](const PreparedContact& c) { return !c.derivation.inert && desired_of(c) > epsilon; });
}

}  // namespace

PhaseOutcome sequential_sweep_velocities(FrameContext& frame) {
    std::vector<RigidBody>& bodies = frame.bodies;
    std::vector<PreparedContact>& contacts = frame.contacts;
    const ResolverSettings& settings = frame.settings;
    Recorder& recorder = frame.recorder;
    PhaseOutcome outcome;
    outcome.iteration_limit = std::max(settings.sweeps, 0) * static_cast<int>(contacts.size());
    const ContactsByBody by_body(contacts, bodies.size());  // so a visit updates its neighbours, not every contact
    std::vector<int> sharing;
    for (int pass = 0; pass < settings.sweeps; ++pass) {
        if (frame.stop_requested()) break;
        bool resolved_any = false;
        for (int i = 0; i < static_cast<int>(contacts.size()); ++i) {
            const PreparedContact& contact = contacts[static_cast<std::size_t>(i)];
            if (contact.derivation.inert || desired_of(contact) <= settings.velocity_epsilon) continue;
            VelocityIteration record{.iteration = outcome.iterations_used,
                                     .contact = i,
                                     .desired_delta_velocity = desired_of(contact),
                                     .epsilon = settings.velocity_epsilon,
                                     .sweep = SweepPlace{0, pass, SolverStage::solve},
                                     .accumulated = {},
                                     .resolution = resolve_velocity(contact, settings.sliding_friction),
                                     .updates = {}};
            const std::array<int, 2> changed = contact.derivation.bodies;
            const VelocityChange& change = record.resolution->velocity_change_terms;
            apply_velocity_change(bodies, changed, change);
            by_body.sharing(changed, sharing);
            update_contact_velocities(contacts, sharing, changed, change, settings,
                                      recorder.wants_updates() ? &record.updates : nullptr);
            recorder.velocity_iteration(record);
            ++outcome.iterations_used;
            resolved_any = true;
        }
        if (!resolved_any) break;
    }
    outcome.stop = any_desired_delta_velocity_above(contacts, settings.velocity_epsilon) ? StopReason::sweeps_complete
                                                                                         : StopReason::resolved;
    recorder.end_phase(Phase::velocity, outcome);
    return outcome;
}

}  // namespace impulse
