// Linear projection: the chapter's first strategy, carried over from particles. The bodies move apart
// along the contact normal, each in proportion to its inverse mass, and never turn. "Unfortunately it
// isn't very realistic": a box resting on one corner slides sideways out of the ground instead of tipping.

#include "methods/projections.hpp"
#include "methods/phases.hpp"

namespace impulse {

PositionResolution linear_projection(const PreparedContact& contact, const PerBody<MassProperties>& mass,
                                     double amount) {
    PositionResolution r;
    r.method = PositionMethod::linear_projection;
    r.penetration = contact.penetration;
    r.amount = amount;
    // Nonlinear projection with every angular inertia taken as zero: all of the move is linear.
    r.inertia.penetration_inertia = 0.0;
    for (int i = 0; i < 2; ++i) {
        if (!mass[i]) continue;
        r.inertia.linear_inertia[i] = mass[i]->inverse_mass;
        r.inertia.angular_inertia[i] = 0.0;
        r.inertia.penetration_inertia += mass[i]->inverse_mass;
    }
    if (r.inertia.penetration_inertia > 0.0) {
        r.moves = move_split(amount, r.inertia);
    } else {
        // Neither body can translate: linear projection has nothing to move.
        for (int i = 0; i < 2; ++i)
            if (mass[i]) r.moves.linear_move[i] = r.moves.angular_move[i] = 0.0;
    }
    // Every angular move is 0: the chain's rotation per unit move is never read.
    r.change =
        position_change(r.moves, contact.basis.normal(),
                        delta_velocity_per_unit_impulse(contact.basis.normal(), relative_positions(contact), mass));
    return r;
}

namespace {

PositionResolution project(const PreparedContact& contact, double amount, const PositionPhaseState& /*state*/,
                           const FrameContext& frame) {
    return linear_projection(contact, mass_of(contact, frame.mass), amount);
}

// A contact whose bodies cannot translate cannot be moved by this method at all.
bool can_translate(const PreparedContact& contact, std::span<const MassProperties> mass) {
    for (const MassProperties* m : contact_mass(contact, mass))
        if (m && m->inverse_mass > 0.0) return true;
    return false;
}

}  // namespace

PhaseOutcome linear_projection_positions(FrameContext& frame) {
    return worst_first_positions(frame, project, can_translate);
}

}  // namespace impulse
