#pragma once
// Small builders for the bodies and contacts tests derive by hand.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "shapes/shape.hpp"
#include "preparation/prepared_contact.hpp"
#include "record/contact_record.hpp"
#include "settings/settings.hpp"

#include <vector>

namespace impulse::test {

inline const Box cube{Vec3(0.5, 0.5, 0.5)};  // a 1 m cube

inline RigidBody sphere(double mass, double radius, const Vec3& position, const Vec3& velocity = Vec3::Zero()) {
    RigidBody b;
    b.position = position;
    b.velocity = velocity;
    b.inverse_mass = 1.0 / mass;
    b.inverse_inertia_body = sphere_inverse_inertia(b.inverse_mass, radius);
    return b;
}

inline RigidBody box(double mass, const Vec3& half_size, const Vec3& position, const Vec3& velocity = Vec3::Zero()) {
    RigidBody b;
    b.position = position;
    b.velocity = velocity;
    b.inverse_mass = 1.0 / mass;
    b.inverse_inertia_body = box_inverse_inertia(b.inverse_mass, half_size);
    return b;
}

inline RigidBody immovable(const Vec3& position = Vec3::Zero()) {
    RigidBody b;
    b.position = position;
    b.inverse_mass = 0.0;
    b.inverse_inertia_body = Mat3::Zero();
    return b;
}

inline Contact contact(int body0, int body1, const Vec3& point, const Vec3& normal, double penetration = 0.0,
                       double restitution = 0.0, double friction = 0.0) {
    return Contact{{body0, body1}, point, normal.normalized(), penetration, restitution, friction};
}

// The chapter's own derivation, without the reference engine's chapter-15 refinements.
inline ResolverSettings plain_settings() {
    ResolverSettings s = *preset("book");
    s.restitution_cutoff = 0.0;
    s.velocity_from_acceleration = false;
    s.tangential_acceleration_velocity = false;
    return s;
}

inline PreparedContact prepared(const Contact& c, const std::vector<RigidBody>& bodies,
                                const ResolverSettings& settings = plain_settings()) {
    const std::vector<MassProperties> mass = mass_properties(bodies);
    std::pmr::vector<PreparedContact> one;
    prepare_contacts({&c, 1}, bodies, mass, settings, one);
    return one.front();
}

// Steps 1-5 of `c` with every intermediate, as the recorder derives them.
inline ContactPreparation derivation(const Contact& c, const std::vector<RigidBody>& bodies,
                                     const ResolverSettings& settings = plain_settings()) {
    return contact_preparation(0, c, bodies, mass_properties(bodies), settings);
}

// The mass of a contact's bodies, as the derivation's steps take it (body 1 empty for the world).
inline PerBody<MassProperties> mass_of(const std::array<int, 2>& contact_bodies, const std::vector<RigidBody>& bodies) {
    PerBody<MassProperties> mass;
    for (int i = 0; i < 2; ++i)
        if (contact_bodies[i] != world_body) {
            const RigidBody& b = bodies[static_cast<std::size_t>(contact_bodies[i])];
            mass[i] = MassProperties{b.inverse_mass, world_inverse_inertia(b)};
        }
    return mass;
}

// Velocity of a body's material point at world position q, straight from the body (9.5).
inline Vec3 point_velocity(const RigidBody& b, const Vec3& q) {
    return b.velocity + b.angular_velocity.cross(q - b.position);
}

}  // namespace impulse::test
