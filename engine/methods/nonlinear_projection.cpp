// Nonlinear projection, the book's method: "we use a combination of linear and angular movement to resolve
// the penetration". Each body moves and turns in proportion to its linear and angular inertia along the
// normal, so a body that resists rotation takes more of its share as linear motion; the angular limit
// stops a small-inertia body from spinning itself out of a deep contact.

#include "methods/projections.hpp"
#include "methods/phases.hpp"

namespace impulse {

PositionResolution nonlinear_projection(const PreparedContact& contact, double amount,
                                        const AngularLimitSettings& limit, OrientationUpdate orientation_update) {
    const ContactPreparation& d = contact.derivation;
    PositionResolution r;
    r.method = PositionMethod::nonlinear_projection;
    r.penetration = contact.penetration;
    r.amount = amount;
    r.inertia = penetration_inertia(d.unit_impulse_chain);
    r.moves = move_split(amount, r.inertia);
    r.angular_limit =
        angular_limit(r.moves, limit, d.normal, d.relative_position, d.unit_impulse_chain, orientation_update);
    r.change = position_change(r.moves, d.normal, d.unit_impulse_chain);
    return r;
}

namespace {

PositionResolution project(const PreparedContact& contact, double amount, const PositionPhaseState& /*state*/,
                           const FrameContext& frame) {
    return nonlinear_projection(contact, amount, frame.settings.angular_limit, frame.settings.orientation_update);
}

}  // namespace

PhaseOutcome nonlinear_projection_positions(FrameContext& frame) {
    return worst_first_positions(frame, project, nullptr);
}

}  // namespace impulse
