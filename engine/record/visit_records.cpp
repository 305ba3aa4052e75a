#include "record/visit_records.hpp"

namespace impulse {

void VisitRecords::begin(const PreparedFrame& frame) {
    contacts_.assign(frame.prepared.begin(), frame.prepared.end());
    mass_.assign(frame.mass.begin(), frame.mass.end());
    refinements_ = velocity_refinements(frame.settings);
    by_body_.emplace(contacts_, mass_.size());
    targets_.clear();
    // v_s + step 5's desired delta v: the bounce and the position bias on top of the velocity it was judged on.
    for (const PreparedContact& c : contacts_)
        targets_.push_back(c.inert ? 0.0 : c.contact_velocity.x() + c.desired_delta_velocity);
}

PositionResolution VisitRecords::push_resolution(const PositionVisit& visit) const {
    const PreparedContact& c = contacts_[static_cast<std::size_t>(visit.contact)];
    const PerBody<Vec3> q_rel = relative_positions(c);
    PositionResolution r;
    r.method = PositionMethod::split_impulse;
    r.penetration = c.penetration;
    r.push_impulse = visit.push_impulse;
    // How readily each body's pseudo velocity gives way along n per unit push: step 3's components.
    r.inertia = penetration_inertia(delta_velocity_per_unit_impulse(c.basis.normal(), q_rel, mass_of(c, mass_)));
    for (int b = 0; b < 2; ++b) {
        if (!q_rel[b]) continue;
        r.moves.linear_move[b] = dot(*visit.change.linear_change[b], c.basis.normal());
        r.moves.angular_move[b] = dot(cross(*visit.change.angular_change[b], *q_rel[b]), c.basis.normal());
    }
    r.change = visit.change;
    return r;
}

PositionIteration VisitRecords::position_iteration(const PositionVisit& visit) {
    const PreparedContact& c = contacts_[static_cast<std::size_t>(visit.contact)];
    PositionIteration it{0,
                         visit.contact,
                         c.penetration,
                         visit.resolution ? visit.epsilon : 0.0,
                         visit.resolution ? std::nullopt : std::optional(visit.slop),
                         visit.pass,
                         visit.resolution ? *visit.resolution : push_resolution(visit),
                         {}};
    record_updates(it.resolution->change, c.bodies, it);
    return it;
}

VelocityResolution VisitRecords::row_resolution(const VelocityVisit& visit) const {
    const PreparedContact& c = contacts_[static_cast<std::size_t>(visit.contact)];
    const AccumulatedImpulse& total = visit.accumulated;
    VelocityResolution r;
    r.contact_velocity = visit.contact_velocity;
    r.desired_terms = visit.desired_terms;
    const bool sliding = total.clamp == ImpulseClamp::friction || total.clamp == ImpulseClamp::both;
    r.impulse_terms.impulse_model = !visit.friction_rows ? ImpulseModel::frictionless
                                    : sliding            ? ImpulseModel::sliding_friction
                                                         : ImpulseModel::static_friction;
    r.impulse_terms.impulse = total.after - total.before;
    r.impulse_terms.impulse_world = to_world(c.basis, r.impulse_terms.impulse);
    r.velocity_change_terms = velocity_change(r.impulse_terms.impulse_world, relative_positions(c), mass_of(c, mass_));
    return r;
}

VelocityIteration VisitRecords::velocity_iteration(const VelocityVisit& visit) {
    const bool accumulating = !visit.resolution;
    VelocityIteration it{.iteration = 0,
                         .contact = visit.contact,
                         .desired_delta_velocity = 0.0,
                         .epsilon = visit.epsilon,
                         .sweep = visit.sweep,
                         .accumulated = std::nullopt,
                         .resolution = accumulating ? row_resolution(visit) : *visit.resolution,
                         .updates = {},
                         .body_visit = std::nullopt,
                         .dual_update = std::nullopt};
    it.desired_delta_velocity = it.resolution->desired_terms.desired_delta_velocity;
    if (accumulating) it.accumulated = visit.accumulated;
    if (visit.updates != DesiredFollows::nothing)
        record_updates(it.resolution->velocity_change_terms, contacts_[static_cast<std::size_t>(visit.contact)].bodies,
                       visit.updates, it);
    return it;
}

void VisitRecords::record_updates(const PositionChange& change, const std::array<int, 2>& moved,
                                  PositionIteration& it) {
    by_body_->sharing(moved, sharing_);
    update_penetrations(
        contacts_, sharing_, moved, change, [&](int index, int slot, int m, double delta, double before) {
            it.updates.push_back(
                {index, moved[m], slot, delta, before, contacts_[static_cast<std::size_t>(index)].penetration});
        });
}

void VisitRecords::record_updates(const VelocityChange& change, const std::array<int, 2>& moved, DesiredFollows follows,
                                  VelocityIteration& it) {
    by_body_->sharing(moved, sharing_);
    const auto updated = [&](int index, int slot, int m, const Vec3& delta, const Vec3& before, double desired_before) {
        const PreparedContact& other = contacts_[static_cast<std::size_t>(index)];
        // The row's target minus the velocity, for a method that keeps its rows' targets (the book's step 5 is
        // still followed on this copy, unread).
        const double target = targets_[static_cast<std::size_t>(index)];
        const bool book = follows == DesiredFollows::step_5;
        it.updates.push_back({index, moved[m], slot, delta, before, other.contact_velocity,
                              book ? desired_before : target - before.x(),
                              book ? other.desired_delta_velocity : target - other.contact_velocity.x()});
    };
    update_contact_velocities(contacts_, sharing_, moved, change, refinements_, updated);
}

}  // namespace impulse
