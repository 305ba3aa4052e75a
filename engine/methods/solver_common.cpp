#include "methods/solver_common.hpp"

namespace impulse {

FrictionMatrices::FrictionMatrices(std::size_t contact_count, std::pmr::memory_resource* scratch)
    : slot_(contact_count, -1, scratch), matrices_(scratch) {}

const FactoredDeltaVelocityMatrix& FrictionMatrices::of(const PreparedContact& contact,
                                                        std::span<const MassProperties> mass) {
    int& slot = slot_[static_cast<std::size_t>(contact.contact)];
    if (slot < 0) {
        slot = static_cast<int>(matrices_.size());
        matrices_.emplace_back(
            delta_velocity_matrix(contact.basis, contact.relative_position, contact_mass(contact, mass)));
    }
    return matrices_[static_cast<std::size_t>(slot)];
}

VelocityResolution resolve_velocity(const PreparedContact& contact, std::span<const MassProperties> mass,
                                    FrictionMatrices& k, const ResolverSettings& settings) {
    VelocityResolution r;
    r.contact_velocity = contact.contact_velocity;
    r.desired_terms = desired_again(contact, velocity_refinements(settings));
    r.impulse_terms =
        calculate_impulse(contact.basis, contact.friction != 0.0 ? &k.of(contact, mass) : nullptr,
                          contact.contact_velocity, contact.desired_delta_velocity,
                          contact.delta_velocity_per_unit_impulse, contact.friction, settings.sliding_friction);
    r.velocity_change_terms =
        velocity_change(r.impulse_terms.impulse_world, relative_positions(contact), mass_of(contact, mass));
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

}  // namespace impulse
