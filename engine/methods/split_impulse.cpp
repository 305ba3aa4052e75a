// The split impulse (Bullet's btSequentialImpulseConstraintSolver with splitImpulse on; Catto calls the idea
// "pseudo-velocities"): penetration is removed by a second projected Gauss-Seidel solve on velocities that
// exist only to move the bodies. Each body gets a pseudo linear and angular velocity, zero at the start of
// every frame; the pushes change only those, the bodies are moved by them over the frame, and they are then
// thrown away. The real velocities never see the push, so separating overlapping bodies adds no kinetic
// energy (Baumgarte's bias does), and the real velocity solve runs without any position bias.
//
// Per contact, the normal row of methods/contact_rows.hpp only (friction has no business moving positions):
//   target          = beta max(penetration - slop, 0) / h     penetration as prepared (methods/position_bias.hpp)
//   v_push          = sum over bodies of +-(pseudo v + pseudo w x q_rel) . n           (9.5, body 0 minus body 1)
//   d lambda        = (target - v_push) / d                   d = step 3's delta velocity per unit impulse
//   lambda          = max(lambda + d lambda, 0)               the accumulated push, never a pull
//   applied push    = lambda after - lambda before, through step 7: pseudo v += velocity_change,
//                     pseudo w += rotation_change
// `sweeps` sweeps over the contacts in index order, stopping early when a whole sweep changed no contact's
// pseudo normal velocity by more than the velocity epsilon. A converged push moves each contact apart by
// beta (penetration - slop) over the frame; the rest is left by design, which the stop reason says
// (sweeps_complete, or resolved when the pushes converged before the last sweep).
//
// The bodies are moved visit by visit, by exactly the change of their pseudo velocities times h (positions
// += d(pseudo v) h, orientations turned by d(pseudo w) h with the configured orientation update). The
// translations sum to pseudo v x h, as moving once at the end would; the turns differ from one turn by
// pseudo w x h only at second order. Moving per visit lets the inspector rebuild every intermediate pose from
// the trace and land exactly on bodies_after.
//
// Recorded per visit, in the position phase's vocabulary (a PositionIteration, pass = sweep index, epsilon =
// the slop): method split_impulse; penetration = the contact's bookkeeping penetration when visited; push_impulse =
// the push impulse applied this visit (N s: a projection's amount is in metres); linear_inertia and angular_inertia =
// step 3's linear and angular components (how readily each body's pseudo velocity gives way along n per unit push), and
// penetration_inertia = d; linear_move and angular_move = how far this visit moved each body's contact point along n
// by translation and by rotation, (linear_change) . n and (angular_change x q_rel) . n, body 1's negative as
// in the book; no angular limit; linear_change and angular_change = the moves applied. The penetration
// updates are the book's linearised bookkeeping (methods/bookkeeping.cpp) of every contact sharing a body,
// kept only while recording (the pushes never read it). The loop is compiled twice from one template, with and
// without the records, on the same arithmetic.

#include "methods/contact_rows.hpp"
#include "methods/method.hpp"
#include "preparation/position_bias.hpp"
#include "methods/bookkeeping.hpp"
#include "methods/worst_first_selector.hpp"

#include <algorithm>
#include <cmath>

namespace impulse {

namespace {

template <bool recording>
PhaseOutcome push_apart(FrameContext& frame) {
    const ResolverSettings& settings = frame.settings;
    std::vector<PreparedContact>& contacts = frame.contacts;
    const double h = settings.duration;
    // The pseudo velocities: zero at the start of every frame, with the bodies' mass as prepared.
    std::pmr::vector<SolverBody> pseudo = solver_bodies(frame.bodies, frame.mass, frame.scratch);
    for (SolverBody& p : pseudo) p.velocity = p.angular_velocity = Vec3::Zero();
    std::pmr::vector<ContactRow> rows(frame.scratch);
    std::pmr::vector<double> targets(frame.scratch);
    std::pmr::vector<int> active(frame.scratch);
    for (const RowPreparation& c : frame.rows) {
        if (!fill_contact_row(rows.emplace_back(), c, pseudo.data(), false)) {  // nothing can push it
            rows.pop_back();
            continue;
        }
        targets.push_back(position_bias(c.penetration, settings.position_bias, h));
        active.push_back(c.contact);
    }

    std::optional<ContactsByBody> by_body;  // a push updates its neighbours' bookkeeping, not every contact
    if constexpr (recording) by_body.emplace(contacts, frame.bodies.size());
    std::vector<int> sharing;
    PhaseOutcome outcome;
    outcome.iteration_limit = std::max(settings.sweeps, 0) * static_cast<int>(rows.size());
    bool converged = rows.empty();
    int pass = 0;
    for (; pass < settings.sweeps && !converged && !frame.stop_requested(); ++pass) {
        double largest = 0.0;
        for (std::size_t r = 0; r < rows.size(); ++r) {
            ContactRow& row = rows[r];
            const RowVisit v = solve_normal_row(row, row_normal_velocity(row, pseudo.data()), NormalTarget{targets[r]});
            keep_total(row, v.after);
            const double push = v.after.n - v.before.n;
            largest = std::max(largest, std::abs(push) / row.normal_mass);

            VelocityChange change;
            apply_impulse(row, pseudo.data(), Vec3(normal_of(row) * push), &change);
            PositionChange moves;
            for (int b = 0; b < 2; ++b) {
                if (row.body[b] < 0) continue;
                moves.linear_change[b] = *change.velocity_change[b] * h;
                moves.angular_change[b] = *change.rotation_change[b] * h;
                RigidBody& body = frame.bodies[static_cast<std::size_t>(row.body[b])];
                body.position += *moves.linear_change[b];
                body.orientation = rotated(body.orientation, *moves.angular_change[b], settings.orientation_update);
            }
            if constexpr (recording) {
                const PreparedContact& contact = contacts[static_cast<std::size_t>(row.contact)];
                const ContactPreparation& d = contact.derivation;
                PositionResolution resolution;
                resolution.method = PositionMethod::split_impulse;
                resolution.penetration = contact.penetration;
                resolution.push_impulse = push;
                resolution.inertia = penetration_inertia(d.unit_impulse_chain);
                for (int b = 0; b < 2; ++b) {
                    if (row.body[b] < 0) continue;
                    resolution.moves.linear_move[b] = moves.linear_change[b]->dot(d.normal);
                    resolution.moves.angular_move[b] =
                        moves.angular_change[b]->cross(*d.relative_position[b]).dot(d.normal);
                }
                resolution.change = moves;
                PositionIteration record{outcome.iterations_used,
                                         row.contact,
                                         contact.penetration,
                                         settings.position_bias.slop,
                                         pass,
                                         resolution,
                                         {}};
                by_body->sharing(d.bodies, sharing);
                update_penetrations(contacts, sharing, d.bodies, moves, &record.updates);
                frame.recorder.position_iteration(record);
            }
            ++outcome.iterations_used;
        }
        converged = largest <= settings.velocity_epsilon;
    }
    if constexpr (!recording)
        if (pass > 0) frame.recorder.contacts_visited(active);
    outcome.stop = converged ? StopReason::resolved : StopReason::sweeps_complete;
    frame.recorder.end_phase(Phase::position, outcome);
    return outcome;
}

}  // namespace

PhaseOutcome split_impulse_positions(FrameContext& frame) {
    return frame.recorder.wants_updates() ? push_apart<true>(frame) : push_apart<false>(frame);
}

}  // namespace impulse
