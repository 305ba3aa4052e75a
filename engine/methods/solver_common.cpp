#include "methods/solver_common.hpp"

#include "derivation/contact_velocity.hpp"
#include "derivation/impulse.hpp"

namespace impulse {

VelocityResolution resolve_velocity(const PreparedContact& contact, SlidingFriction sliding) {
    const ContactPreparation& d = contact.derivation;
    VelocityResolution r;
    r.contact_velocity = contact.contact_velocity;
    r.desired_terms = contact.desired_terms;
    r.impulse_terms = calculate_impulse(d.basis, d.friction != 0.0 ? &delta_velocity_matrix_of(contact) : nullptr,
                                        contact.contact_velocity, contact.desired_terms.desired_delta_velocity,
                                        d.unit_impulse_chain.delta_velocity_per_unit_impulse, d.friction, sliding);
    r.velocity_change_terms = velocity_change(r.impulse_terms.impulse_world, d.relative_position, contact.mass);
    return r;
}

void apply_velocity_change(std::vector<RigidBody>& bodies, const std::array<int, 2>& changed,
                           const VelocityChange& change) {
    for (int i = 0; i < 2; ++i) {
        if (changed[i] == world_body) continue;
        RigidBody& body = bodies[static_cast<std::size_t>(changed[i])];
        body.velocity += *change.velocity_change[i];
        body.angular_velocity += *change.rotation_change[i];
    }
}

Vec3 current_contact_velocity(const PreparedContact& contact, std::span<const RigidBody> bodies,
                              const ResolverSettings& settings) {
    const ContactPreparation& d = contact.derivation;
    PerBody<BodyMotion> motion;
    for (int i = 0; i < 2; ++i) {
        if (d.bodies[i] == world_body) continue;
        const RigidBody& body = bodies[static_cast<std::size_t>(d.bodies[i])];
        motion[i] = BodyMotion{body.velocity, body.angular_velocity, body.last_frame_acceleration};
    }
    return contact_velocity(d.basis, d.relative_position, motion, settings.duration,
                            settings.tangential_acceleration_velocity)
        .contact_velocity;
}

}  // namespace impulse
