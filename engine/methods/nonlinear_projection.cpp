// Nonlinear projection, the book's method: "we use a combination of linear and angular movement to resolve
// the penetration". Each body moves and turns in proportion to its linear and angular inertia along the
// normal, so a body that resists rotation takes more of its share as linear motion; the angular limit
// stops a small-inertia body from spinning itself out of a deep contact.

#include "methods/projections.hpp"
#include "methods/phases.hpp"

namespace impulse {

PositionResolution nonlinear_projection(const PreparedContact& contact, const PerBody<MassProperties>& mass,
                                        double amount, const AngularLimitSettings& limit,
                                        OrientationUpdate orientation_update) {
    const Vec3 normal = contact.basis.normal();
    const PerBody<Vec3> q_rel = relative_positions(contact);
    // "To resolve penetration we use exactly the same sequence of equations": step 3's chain, whose d the
    // preparation computed by the same functions.
    const UnitImpulseChain chain = delta_velocity_per_unit_impulse(normal, q_rel, mass);
    PositionResolution r;
    r.method = PositionMethod::nonlinear_projection;
    r.penetration = contact.penetration;
    r.amount = amount;
    r.inertia = penetration_inertia(chain);
    const LimitedMoves limited =
        angular_limit(move_split(amount, r.inertia), limit, normal, q_rel, chain, orientation_update);
    r.moves = limited.moves;
    r.angular_limit = limited.limit;
    r.change = position_change(r.moves, normal, chain);
    return r;
}

namespace {

PositionResolution project(const PreparedContact& contact, double amount, const PositionPhaseState& /*state*/,
                           const FrameContext& frame) {
    return nonlinear_projection(contact, mass_of(contact, frame.mass), amount, frame.settings.angular_limit,
                                frame.settings.orientation_update);
}

}  // namespace

PhaseOutcome nonlinear_projection_positions(FrameContext& frame) {
    return worst_first_positions(frame, project, nullptr);
}

}  // namespace impulse
