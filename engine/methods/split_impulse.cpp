// The split impulse (Bullet's btSequentialImpulseConstraintSolver with splitImpulse on; Catto calls the idea
// "pseudo-velocities"): penetration is removed by a second projected Gauss-Seidel solve on velocities that
// exist only to move the bodies. Each body gets a pseudo linear and angular velocity, zero at the start of
// every frame; the pushes change only those, the bodies are moved by them over the frame, and they are then
// thrown away. The real velocities never see the push, so separating overlapping bodies adds no kinetic
// energy (Baumgarte's bias does), and the real velocity solve runs without any position bias.
//
// Per contact, the normal row of methods/contact_rows.hpp only (friction has no business moving positions):
//   target          = beta max(penetration - slop, 0) / h     penetration as prepared (settings/settings.hpp)
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
// Reported per visit: the push impulse applied this visit (N s: a projection's amount is in metres), the moves it
// made and the slop; record/visit_records.hpp builds the record in the position phase's words (step 3's inertias,
// how far the visit moved each body's contact point along n, the penetration updates of the contacts sharing a body).

#include "methods/contact_rows.hpp"
#include "methods/method.hpp"

#include <algorithm>
#include <cmath>

namespace impulse {

PhaseOutcome split_impulse_positions(FrameContext& frame) {
    const ResolverSettings& settings = frame.settings;
    const double h = settings.duration;
    // The pseudo velocities: zero at the start of every frame, with the bodies' mass as prepared.
    std::pmr::vector<SolverBody> pseudo = solver_bodies(frame.bodies, frame.mass, frame.scratch);
    for (SolverBody& p : pseudo) p.velocity = p.angular_velocity = Vec3::Zero();
    std::pmr::vector<ContactRow> rows(frame.scratch);
    std::pmr::vector<double> targets(frame.scratch);
    for (const PreparedContact& c : frame.contacts) {
        if (!can_move(c)) continue;  // nothing can push it
        fill_contact_row(rows.emplace_back(), c, pseudo.data(), FrictionFill::none);
        targets.push_back(position_bias(c.penetration, settings.position_bias, h));
    }

    // A sweep's pushes and moves, kept for the recorder and reported after the sweep (as the accumulating velocity
    // methods keep theirs: a call in the loop would keep every value alive across it).
    struct KeptPush {
        double push = 0.0;
        PositionChange moves;
    };
    std::pmr::vector<KeptPush> kept(frame.keeping ? rows.size() : 0, frame.scratch);
    PhaseOutcome outcome;
    outcome.iteration_limit = std::max(settings.sweeps, 0) * static_cast<int>(rows.size());
    bool converged = rows.empty();
    for (int pass = 0; pass < settings.sweeps && !converged && !frame.stop_requested(); ++pass) {
        double largest = 0.0;
        for (std::size_t r = 0; r < rows.size(); ++r) {
            ContactRow& row = rows[r];
            const RowVisit v = solve_normal_row(row, row_velocity(row, pseudo.data()).n, NormalTarget{targets[r]});
            keep_total(row, v.after);
            const double push = v.after.n - v.before.n;
            largest = std::max(largest, std::abs(push) / row.normal_mass);
            // The push through step 7 on the pseudo velocities, and the bodies moved by exactly that change times h.
            PositionChange moves;
            for (int b = 0; b < 2; ++b) {
                if (row.body[b] < 0) continue;
                SolverBody& body = pseudo[static_cast<std::size_t>(row.body[b])];
                const BodyVelocityChange change =
                    body_velocity_change(body_sign(b) * push * normal_of(row), row.anchor[b], body.mass);
                body.velocity += change.velocity_change;
                body.angular_velocity += change.rotation_change;
                moves.linear_change[b] = change.velocity_change * h;
                moves.angular_change[b] = change.rotation_change * h;
                RigidBody& moved = frame.bodies[static_cast<std::size_t>(row.body[b])];
                moved.position += *moves.linear_change[b];
                moved.orientation = rotated(moved.orientation, *moves.angular_change[b], settings.orientation_update);
            }
            if (!kept.empty()) [[unlikely]]
                kept[r] = {push, moves};
        }
        outcome.iterations_used += static_cast<int>(rows.size());
        for (std::size_t r = 0; r < kept.size(); ++r)
            frame.recorder.position_visit({.contact = rows[r].contact,
                                           .pass = pass,
                                           .resolution = nullptr,
                                           .push_impulse = kept[r].push,
                                           .change = kept[r].moves,
                                           .slop = settings.position_bias.slop});
        converged = largest <= settings.velocity_epsilon;
    }
    // Every sweep visits every row in order: the last sweep holds each contact's last visit, stamped once, here.
    if (frame.touch && outcome.iterations_used > 0)
        for (const ContactRow& row : rows) frame.touch->touched(row.contact);
    outcome.stop = converged ? StopReason::resolved : StopReason::sweeps_complete;
    return outcome;
}

}  // namespace impulse
