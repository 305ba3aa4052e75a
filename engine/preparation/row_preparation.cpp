#include "preparation/row_preparation.hpp"

namespace impulse {

namespace {

// Step 2's relative positions as the rows keep them: zero for the world.
std::array<Vec3, 2> anchors(const PerBody<Vec3>& relative_position) {
    return {relative_position[0] ? *relative_position[0] : Vec3::Zero(),
            relative_position[1] ? *relative_position[1] : Vec3::Zero()};
}

// The other way round: empty for the world, as steps 4 and 5 take them.
PerBody<Vec3> relative_positions(const RowPreparation& row) {
    PerBody<Vec3> q_rel;
    for (int i = 0; i < 2; ++i)
        if (row.bodies[i] != world_body) q_rel[i] = row.relative_position[i];
    return q_rel;
}

RowVelocity row_velocity(const ContactVelocityTerms& velocity, const DesiredDeltaVelocity& desired) {
    RowVelocity v;
    v.separating_velocity = velocity.contact_velocity.x();
    // Body 0's term minus body 1's, from 0, in step 4's order.
    for (int i = 0; i < 2; ++i)
        if (const std::optional<Vec3>& term = velocity.tangential_acceleration_velocity[i]) {
            v.tangential_acceleration_velocity[0] += body_sign(i) * term->y();
            v.tangential_acceleration_velocity[1] += body_sign(i) * term->z();
        }
    v.desired_delta_velocity = desired.desired_delta_velocity;
    return v;
}

}  // namespace

RowPreparation row_preparation(const PreparedContact& prepared) {
    const ContactPreparation& d = prepared.derivation;
    return {.contact = d.contact,
            .swapped = d.swapped,
            .bodies = d.bodies,
            .origin = d.origin,
            .basis = d.basis,
            .relative_position = anchors(d.relative_position),
            .penetration = d.penetration,
            .restitution = d.restitution,
            .friction = d.friction,
            .velocity = row_velocity(d.velocity_terms, d.desired_terms)};
}

RowPreparation prepare_row(int index, const Contact& contact, std::span<const RigidBody> bodies,
                           const ResolverSettings& settings, bool with_velocity) {
    // prepare_contact's steps, with the same functions on the same inputs (prepared_contact.cpp).
    const OrientedContact o = oriented(contact);
    RowPreparation row{.contact = index,
                       .swapped = o.swapped,
                       .bodies = o.bodies,
                       .origin = o.origin,
                       .basis = basis(o.normal),  // step 1
                       .relative_position = {},
                       .penetration = contact.penetration,
                       .restitution = contact.restitution,
                       .friction = contact.friction,
                       .velocity = std::nullopt};
    for (int b = 0; b < 2; ++b)  // step 2: q - p (1.8)
        row.relative_position[b] = o.bodies[b] == world_body
                                       ? Vec3::Zero()
                                       : Vec3(contact.point - bodies[static_cast<std::size_t>(o.bodies[b])].position);
    if (!with_velocity) return row;
    const PerBody<BodyMotion> motion = contact_motion(o.bodies, bodies);
    const ContactVelocityTerms velocity = contact_velocity(
        row.basis, relative_positions(row), motion, settings.duration, settings.tangential_acceleration_velocity);
    const DesiredDeltaVelocity desired =
        desired_delta_velocity(velocity.contact_velocity.x(), contact.restitution, o.normal, motion, settings.duration,
                               velocity_refinements(settings), step_5_position_bias(contact.penetration, settings));
    row.velocity = row_velocity(velocity, desired);
    return row;
}

void prepare_rows(std::span<const Contact> contacts, std::span<const RigidBody> bodies,
                  const ResolverSettings& settings, bool with_velocity, std::pmr::vector<RowPreparation>& rows) {
    rows.clear();
    rows.reserve(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i)
        rows.push_back(prepare_row(static_cast<int>(i), contacts[i], bodies, settings, with_velocity));
}

double separating_velocity(const RowPreparation& row, std::span<const RigidBody> bodies,
                           const ResolverSettings& settings) {
    if (row.velocity) return row.velocity->separating_velocity;
    return contact_velocity(row.basis, relative_positions(row), contact_motion(row.bodies, bodies), settings.duration,
                            settings.tangential_acceleration_velocity)
        .contact_velocity.x();
}

}  // namespace impulse
