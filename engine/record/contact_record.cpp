#include "record/contact_record.hpp"

#include "derivation/relative_position.hpp"
#include "preparation/prepared_contact.hpp"

namespace impulse {

ContactPreparation contact_preparation(int index, const Contact& contact, std::span<const RigidBody> bodies,
                                       std::span<const MassProperties> mass, const ResolverSettings& settings) {
    const OrientedContact o = oriented(contact);
    // What the steps need of each body (nothing of the world).
    const std::array<bool, 2> present{o.bodies[0] != world_body, o.bodies[1] != world_body};
    const auto body = [&o](int i) { return static_cast<std::size_t>(o.bodies[i]); };
    const PerBody<MassProperties> body_mass = per_body(present, [&](int i) { return mass[body(i)]; });
    const PerBody<BodyMotion> motion = contact_motion(o.bodies, bodies);
    const Basis contact_basis = basis(o.normal);
    // Each body's own point (they differ only on a recycled contact; the swap exchanged them).
    const PerBody<Vec3> q_rel = per_body(present, [&](int i) {
        const Vec3& point = touch_point(contact, o.swapped ? 1 - i : i);
        return *relative_position(point, {bodies[body(i)].position, std::nullopt})[0];
    });
    const UnitImpulseChain chain = delta_velocity_per_unit_impulse(o.normal, q_rel, body_mass);
    const ContactVelocityTerms velocity =
        contact_velocity(contact_basis, q_rel, motion, settings.duration, settings.tangential_acceleration_velocity);
    const DesiredDeltaVelocity desired =
        desired_delta_velocity(velocity.contact_velocity.x(), contact.restitution, o.normal, motion, settings.duration,
                               velocity_refinements(settings), step_5_position_bias(contact.penetration, settings));
    return {.contact = index,
            .swapped = o.swapped,
            .bodies = o.bodies,
            .point = touch_point(contact, o.swapped ? 1 : 0),
            .body1_point =
                contact.body1_point ? std::optional<Vec3>(touch_point(contact, o.swapped ? 0 : 1)) : std::nullopt,
            .normal = o.normal,
            .penetration = contact.penetration,
            .restitution = contact.restitution,
            .friction = contact.friction,
            .origin = o.origin,
            .inert = chain.delta_velocity_per_unit_impulse <= 0.0,
            .basis = contact_basis,
            .relative_position = q_rel,
            .unit_impulse_chain = chain,
            .velocity_terms = velocity,
            .desired_terms = desired};
}

}  // namespace impulse
