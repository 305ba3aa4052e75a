#include "preparation/prepared_contact.hpp"

#include "preparation/bookkeeping.hpp"

#include <limits>
#include <utility>

namespace impulse {

std::vector<MassProperties> mass_properties(std::span<const RigidBody> bodies) {
    std::vector<MassProperties> mass;
    mass.reserve(bodies.size());
    for (const RigidBody& body : bodies) mass.push_back({body.inverse_mass, world_inverse_inertia(body)});
    return mass;
}

OrientedContact oriented(const Contact& contact) {
    OrientedContact o{contact.bodies[0] == world_body, contact.bodies, contact.origin, contact.normal};
    if (o.swapped) {
        std::swap(o.bodies[0], o.bodies[1]);
        std::swap(o.origin.features[0], o.origin.features[1]);
        o.normal = -o.normal;
    }
    return o;
}

PerBody<BodyMotion> contact_motion(const std::array<int, 2>& ids, std::span<const RigidBody> bodies) {
    const auto motion_of = [&](int i) -> std::optional<BodyMotion> {
        if (ids[i] == world_body) return std::nullopt;
        const RigidBody& body = bodies[static_cast<std::size_t>(ids[i])];
        return BodyMotion{body.velocity, body.angular_velocity, body.last_frame_acceleration};
    };
    return {motion_of(0), motion_of(1)};
}

std::optional<double> step_5_position_bias(double penetration, const ResolverSettings& settings) {
    if (!settings.baumgarte) return std::nullopt;
    return position_bias(penetration, settings.position_bias, settings.duration);
}

namespace {

// One contact's preparation, into `c` (a vector's element, built where it is kept).
void prepare(PreparedContact& c, int index, const Contact& contact, std::span<const RigidBody> bodies,
             std::span<const MassProperties> mass, const ResolverSettings& settings, Preparation preparation) {
    const bool in_full = preparation == Preparation::steps_1_to_5;
    const OrientedContact o = oriented(contact);
    c.contact = index;
    c.bodies = o.bodies;
    c.swapped = o.swapped;
    c.origin = o.origin;
    c.restitution = contact.restitution;
    c.friction = contact.friction;
    c.penetration = contact.penetration;
    c.basis = basis(o.normal);  // step 1
    // Steps 2 to 4 per body, by the derivation's kernels (the same the recorder's records are made by).
    ContactMass body_mass{nullptr, nullptr};
    std::array<const Vec3*, 2> acceleration{nullptr, nullptr};
    c.contact_velocity = Vec3::Zero();
    c.tangential_acceleration_velocity = {0.0, 0.0};
    for (int i = 0; i < 2; ++i) {
        c.relative_position[i] = Vec3::Zero();
        if (o.bodies[i] == world_body) continue;
        const RigidBody& body = bodies[static_cast<std::size_t>(o.bodies[i])];
        body_mass[i] = &mass[static_cast<std::size_t>(o.bodies[i])];
        acceleration[i] = &body.last_frame_acceleration;
        // q - p  (1.8), q the body's own point (a recycled contact keeps one per body; the swap exchanged them)
        c.relative_position[i] = touch_point(contact, o.swapped ? 1 - i : i) - body.position;
        const BodyContactVelocity v =
            body_contact_velocity(c.basis.contact_to_world, c.relative_position[i],
                                  {body.velocity, body.angular_velocity, body.last_frame_acceleration},
                                  settings.duration, in_full && settings.tangential_acceleration_velocity);
        c.contact_velocity += body_sign(i) * v.local;
        c.tangential_acceleration_velocity[0] += body_sign(i) * v.tangential_acceleration_velocity.y();
        c.tangential_acceleration_velocity[1] += body_sign(i) * v.tangential_acceleration_velocity.z();
    }
    c.delta_velocity_per_unit_impulse = delta_velocity_per_unit_impulse(o.normal, c.relative_position, body_mass);
    c.inert = c.delta_velocity_per_unit_impulse <= 0.0;
    if (!in_full) {
        const double unset = std::numeric_limits<double>::quiet_NaN();
        c.tangential_acceleration_velocity = {unset, unset};
        c.velocity_from_acceleration = unset;
        c.position_bias = std::nullopt;
        c.desired_delta_velocity = unset;
        return;
    }
    const VelocityRefinements refinements = velocity_refinements(settings);
    c.velocity_from_acceleration = velocity_from_acceleration(o.normal, acceleration, settings.duration, refinements);
    c.position_bias = step_5_position_bias(contact.penetration, settings);
    c.desired_delta_velocity = desired_again(c, refinements).desired_delta_velocity;  // step 5
}

}  // namespace

void prepare_contacts(std::span<const Contact> contacts, std::span<const RigidBody> bodies,
                      std::span<const MassProperties> mass, const ResolverSettings& settings,
                      std::pmr::vector<PreparedContact>& prepared, Preparation preparation) {
    // Each one made where it is kept, right after its room is taken (not the whole list first: it is larger than
    // the cache, and would be written twice).
    prepared.clear();
    prepared.reserve(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i)
        prepare(prepared.emplace_back(), static_cast<int>(i), contacts[i], bodies, mass, settings, preparation);
}

ContactMass contact_mass(const PreparedContact& contact, std::span<const MassProperties> mass) {
    const auto of = [&](int i) {
        return contact.bodies[i] == world_body ? nullptr : &mass[static_cast<std::size_t>(contact.bodies[i])];
    };
    return {of(0), of(1)};
}

PerBody<MassProperties> mass_of(const PreparedContact& contact, std::span<const MassProperties> mass) {
    const ContactMass m = contact_mass(contact, mass);
    return {m[0] ? std::optional(*m[0]) : std::nullopt, m[1] ? std::optional(*m[1]) : std::nullopt};
}

PerBody<Vec3> relative_positions(const PreparedContact& contact) {
    PerBody<Vec3> q_rel;
    for (int i = 0; i < 2; ++i)
        if (contact.bodies[i] != world_body) q_rel[i] = contact.relative_position[i];
    return q_rel;
}

ContactKey contact_key(const PreparedContact& contact) {
    ContactKey key{contact.bodies, contact.origin};
    if (contact.swapped) {
        std::swap(key.bodies[0], key.bodies[1]);
        std::swap(key.origin.features[0], key.origin.features[1]);
    }
    return key;
}

}  // namespace impulse
