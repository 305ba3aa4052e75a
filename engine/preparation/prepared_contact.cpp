#include "preparation/prepared_contact.hpp"

#include "derivation/relative_position.hpp"
#include "preparation/position_bias.hpp"

#include <utility>

namespace impulse {

const FactoredDeltaVelocityMatrix& delta_velocity_matrix_of(const PreparedContact& contact) {
    if (!contact.delta_velocity_matrix.value) {
        const ContactPreparation& d = contact.derivation;
        contact.delta_velocity_matrix.value =
            factored_delta_velocity_matrix(d.basis, d.relative_position, contact.mass);
    }
    return *contact.delta_velocity_matrix.value;
}

std::vector<MassProperties> mass_properties(std::span<const RigidBody> bodies) {
    std::vector<MassProperties> mass;
    mass.reserve(bodies.size());
    for (const RigidBody& body : bodies) mass.push_back({body.inverse_mass, world_inverse_inertia(body)});
    return mass;
}

PreparedContact prepare_contact(int index, const Contact& contact, std::span<const RigidBody> bodies,
                                std::span<const MassProperties> mass, const ResolverSettings& settings) {
    // Body 0 must be a body: a contact given as (world, body) becomes (body, world) with the normal
    // reversed, so the normal still points towards body 0.
    const bool swapped = contact.bodies[0] == world_body;
    std::array<int, 2> ids = contact.bodies;
    ContactOrigin origin = contact.origin;
    Vec3 normal = contact.normal;
    if (swapped) {
        std::swap(ids[0], ids[1]);
        std::swap(origin.features[0], origin.features[1]);
        normal = -normal;
    }

    // What the steps need of each body (nothing of the world).
    const auto body_of = [&](int i) -> const RigidBody* {
        return ids[i] == world_body ? nullptr : &bodies[static_cast<std::size_t>(ids[i])];
    };
    const auto centre = [&](int i) -> std::optional<Vec3> {
        if (const RigidBody* body = body_of(i)) return body->position;
        return std::nullopt;
    };
    const auto mass_of = [&](int i) -> std::optional<MassProperties> {
        if (body_of(i)) return mass[static_cast<std::size_t>(ids[i])];
        return std::nullopt;
    };
    const auto motion_of = [&](int i) -> std::optional<BodyMotion> {
        if (const RigidBody* body = body_of(i))
            return BodyMotion{body->velocity, body->angular_velocity, body->last_frame_acceleration};
        return std::nullopt;
    };
    const PerBody<MassProperties> body_mass{mass_of(0), mass_of(1)};
    const PerBody<BodyMotion> motion{motion_of(0), motion_of(1)};

    // Steps 1-5.
    const Basis contact_basis = basis(normal);
    const PerBody<Vec3> q_rel = relative_position(contact.point, {centre(0), centre(1)});
    const UnitImpulseChain chain = delta_velocity_per_unit_impulse(normal, q_rel, body_mass);
    const ContactVelocityTerms velocity =
        contact_velocity(contact_basis, q_rel, motion, settings.duration, settings.tangential_acceleration_velocity);
    const std::optional<double> bias =
        settings.baumgarte
            ? std::optional(position_bias(contact.penetration, settings.position_bias, settings.duration))
            : std::nullopt;
    const DesiredDeltaVelocity desired =
        desired_delta_velocity(velocity.contact_velocity.x(), contact.restitution, normal, motion, settings.duration,
                               velocity_refinements(settings), bias);

    // Built in one piece, every member from its value: a PreparedContact declared first and filled in after
    // would first clear its half kilobyte of optional per-body values, then overwrite them.
    return PreparedContact{.penetration = contact.penetration,
                           .contact_velocity = velocity.contact_velocity,
                           .desired_terms = desired,  // the bookkeeping starts from steps 4 and 5
                           .derivation = {.contact = index,
                                          .swapped = swapped,
                                          .bodies = ids,
                                          .point = contact.point,
                                          .normal = normal,
                                          .penetration = contact.penetration,
                                          .restitution = contact.restitution,
                                          .friction = contact.friction,
                                          .origin = origin,
                                          .inert = chain.delta_velocity_per_unit_impulse <= 0.0,
                                          .basis = contact_basis,
                                          .relative_position = q_rel,
                                          .unit_impulse_chain = chain,
                                          .velocity_terms = velocity,
                                          .desired_terms = desired},
                           .mass = body_mass,
                           .delta_velocity_matrix = {}};
}

namespace {

// One contact's preparation, made where the vector keeps it: emplace_back constructs the element from this by
// calling the conversion, and the PreparedContact it returns initializes the element itself. (push_back of
// prepare_contact's result would build it on the stack and then copy its 1.2 kB into the vector.)
struct PreparationOf {
    int index;
    const Contact& contact;
    std::span<const RigidBody> bodies;
    std::span<const MassProperties> mass;
    const ResolverSettings& settings;

    operator PreparedContact() const { return prepare_contact(index, contact, bodies, mass, settings); }
};

}  // namespace

std::vector<PreparedContact> prepare_contacts(std::span<const Contact> contacts, std::span<const RigidBody> bodies,
                                              std::span<const MassProperties> mass, const ResolverSettings& settings) {
    std::vector<PreparedContact> prepared;
    prepared.reserve(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i)
        prepared.emplace_back(PreparationOf{static_cast<int>(i), contacts[i], bodies, mass, settings});
    return prepared;
}

}  // namespace impulse
