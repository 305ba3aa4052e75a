// The split impulse (Bullet's btSequentialImpulseConstraintSolver with splitImpulse on; Catto calls the idea
// "pseudo-velocities"): penetration is removed by a second projected Gauss-Seidel solve on velocities that
// exist only to move the bodies. Each body gets a pseudo linear and angular velocity, zero at the start of
// every frame; the pushes change only those, the bodies are moved by them over the frame, and they are then
// thrown away. The real velocities never see the push, so separating overlapping bodies adds no kinetic
// energy (Baumgarte's bias does), and the real velocity solve runs without any position bias.
//
// Per contact, normal row only (friction has no business moving positions):
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
// the slop): method split_impulse; penetration = the contact's bookkeeping penetration when visited; amount =
// the push impulse applied this visit (N s, not metres); linear_inertia and angular_inertia = step 3's linear
// and angular components (how readily each body's pseudo velocity gives way along n per unit push), and
// total_inertia = d; linear_move and angular_move = how far this visit moved each body's contact point along n
// by translation and by rotation, (linear_change) . n and (angular_change x q_rel) . n, body 1's negative as
// in the book; no angular limit; linear_change and angular_change = the moves applied. The penetration
// updates are the book's linearised bookkeeping (resolver/bookkeeping.cpp) of every contact sharing a body.

#include "derivation/velocity_change.hpp"
#include "methods/position_bias.hpp"
#include "resolver/bookkeeping.hpp"
#include "resolver/phases.hpp"

#include <algorithm>
#include <cmath>

namespace impulse {

namespace {

struct PseudoVelocity {
    Vec3 linear = Vec3::Zero();
    Vec3 angular = Vec3::Zero();
};

// v_push: the pseudo separating velocity of the contact points along the normal.
double push_velocity(const ContactPreparation& d, const std::vector<PseudoVelocity>& pseudo) {
    double v = 0.0;
    for (int i = 0; i < 2; ++i) {
        if (d.bodies[i] == world_body) continue;
        const PseudoVelocity& p = pseudo[static_cast<std::size_t>(d.bodies[i])];
        v += body_sign(i) * (p.linear + p.angular.cross(*d.relative_position[i])).dot(d.normal);
    }
    return v;
}

}  // namespace

PhaseOutcome split_impulse_positions(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                                     const ResolverSettings& settings, Recorder& recorder) {
    const double h = settings.duration;
    std::vector<PseudoVelocity> pseudo(bodies.size());
    std::vector<double> targets, totals(contacts.size(), 0.0);
    targets.reserve(contacts.size());
    int active = 0;
    for (const PreparedContact& c : contacts) {
        targets.push_back(position_bias(c.derivation.penetration, settings.position_bias, h));
        if (!c.derivation.inert) ++active;
    }

    const ContactsByBody by_body(contacts, bodies.size());  // a push updates its neighbours, not every contact
    std::vector<int> sharing;
    PhaseOutcome outcome;
    outcome.iteration_limit = std::max(settings.sweeps, 0) * active;
    bool converged = active == 0;
    for (int pass = 0; pass < settings.sweeps && !converged; ++pass) {
        double largest = 0.0;
        for (int i = 0; i < static_cast<int>(contacts.size()); ++i) {
            const auto index = static_cast<std::size_t>(i);
            const PreparedContact& contact = contacts[index];
            const ContactPreparation& d = contact.derivation;
            if (d.inert) continue;
            const double delta_velocity_per_unit_impulse = d.velocity_per_unit_impulse.delta_velocity_per_unit_impulse;
            const double before = totals[index];
            totals[index] =
                std::max(before + (targets[index] - push_velocity(d, pseudo)) / delta_velocity_per_unit_impulse, 0.0);
            const double push = totals[index] - before;
            largest = std::max(largest, std::abs(push) * delta_velocity_per_unit_impulse);

            const VelocityChange change = velocity_change(d.normal * push, d.relative_position, contact.mass);
            PositionResolution r;
            r.method = PositionMethod::split_impulse;
            r.penetration = contact.penetration;
            r.amount = push;
            r.inertia = penetration_inertia(d.velocity_per_unit_impulse);
            for (int b = 0; b < 2; ++b) {
                if (d.bodies[b] == world_body) continue;
                PseudoVelocity& p = pseudo[static_cast<std::size_t>(d.bodies[b])];
                p.linear += *change.velocity_change[b];
                p.angular += *change.rotation_change[b];
                const Vec3 linear_change = *change.velocity_change[b] * h;
                const Vec3 angular_change = *change.rotation_change[b] * h;
                r.change.linear_change[b] = linear_change;
                r.change.angular_change[b] = angular_change;
                r.moves.linear_move[b] = linear_change.dot(d.normal);
                r.moves.angular_move[b] = angular_change.cross(*d.relative_position[b]).dot(d.normal);
                RigidBody& body = bodies[static_cast<std::size_t>(d.bodies[b])];
                body.position += linear_change;
                body.orientation = rotated(body.orientation, angular_change, settings.orientation_update);
            }
            PositionIteration record{
                outcome.iterations_used, i, contact.penetration, settings.position_bias.slop, pass, r, {}};
            by_body.sharing(d.bodies, sharing);
            update_penetrations(contacts, sharing, d.bodies, r.change,
                                recorder.wants_updates() ? &record.updates : nullptr);
            recorder.position_iteration(record);
            ++outcome.iterations_used;
        }
        converged = largest <= settings.velocity_epsilon;
    }
    outcome.stop = converged ? StopReason::resolved : StopReason::sweeps_complete;
    recorder.end_phase(Phase::position, outcome);
    return outcome;
}

}  // namespace impulse
