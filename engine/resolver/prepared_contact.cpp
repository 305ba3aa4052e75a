#include "resolver/prepared_contact.hpp"

#include "derivation/relative_position.hpp"
#include "methods/position_bias.hpp"

#include <utility>

namespace impulse {

std::vector<MassProperties> mass_properties(std::span<const RigidBody> bodies) {
    std::vector<MassProperties> mass;
    mass.reserve(bodies.size());
    for (const RigidBody& body : bodies) mass.push_back({body.inverse_mass, world_inverse_inertia(body)});
    return mass;
}

PreparedContact prepare_contact(int index, const Contact& contact, std::span<const RigidBody> bodies,
                                std::span<const MassProperties> mass, const ResolverSettings& settings) {
    PreparedContact p;
    ContactPreparation& d = p.derivation;
    d.contact = index;
    d.bodies = contact.bodies;
    d.normal = contact.normal;
    // Body 0 must be a body: a contact given as (world, body) becomes (body, world) with the normal
    // reversed, so the normal still points towards body 0.
    d.origin = contact.origin;
    d.swapped = d.bodies[0] == world_body;
    if (d.swapped) {
        std::swap(d.bodies[0], d.bodies[1]);
        std::swap(d.origin.features[0], d.origin.features[1]);
        d.normal = -d.normal;
    }
    d.point = contact.point;
    d.penetration = contact.penetration;
    d.restitution = contact.restitution;
    d.friction = contact.friction;

    PerBody<Vec3> centres;
    for (int i = 0; i < 2; ++i) {
        if (d.bodies[i] == world_body) continue;
        const RigidBody& body = bodies[static_cast<std::size_t>(d.bodies[i])];
        centres[i] = body.position;
        p.mass[i] = mass[static_cast<std::size_t>(d.bodies[i])];
        p.motion[i] = BodyMotion{body.velocity, body.angular_velocity, body.last_frame_acceleration};
    }

    d.basis = basis(d.normal);
    d.relative_position = relative_position(d.point, centres);
    d.velocity_per_unit_impulse = velocity_per_unit_impulse(d.normal, d.relative_position, p.mass);
    d.inert = d.velocity_per_unit_impulse.delta_velocity_per_unit_impulse <= 0.0;
    d.contact_velocity = contact_velocity(d.basis, d.relative_position, p.motion, settings.duration,
                                          settings.refinements.tangential_acceleration_velocity);
    const std::optional<double> bias =
        settings.baumgarte ? std::optional(position_bias(d.penetration, settings.position_bias, settings.duration))
                           : std::nullopt;
    d.desired_delta_velocity = desired_delta_velocity(d.contact_velocity.contact_velocity.x(), d.restitution, d.normal,
                                                      p.motion, settings.duration, settings.refinements, bias);

    p.penetration = d.penetration;
    p.contact_velocity = d.contact_velocity.contact_velocity;
    p.desired_delta_velocity = d.desired_delta_velocity;
    return p;
}

std::vector<PreparedContact> prepare_contacts(std::span<const Contact> contacts, std::span<const RigidBody> bodies,
                                              std::span<const MassProperties> mass, const ResolverSettings& settings) {
    std::vector<PreparedContact> prepared;
    prepared.reserve(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i)
        prepared.push_back(prepare_contact(static_cast<int>(i), contacts[i], bodies, mass, settings));
    return prepared;
}

}  // namespace impulse
