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

PreparedContact prepare_contact(int index, const Contact& contact, std::span<const RigidBody> bodies,
                                std::span<const MassProperties> mass, const ResolverSettings& settings) {
    const OrientedContact o = oriented(contact);

    // What the steps need of each body (nothing of the world).
    const auto centre = [&](int i) -> std::optional<Vec3> {
        if (o.bodies[i] == world_body) return std::nullopt;
        return bodies[static_cast<std::size_t>(o.bodies[i])].position;
    };
    const auto mass_of = [&](int i) -> std::optional<MassProperties> {
        if (o.bodies[i] == world_body) return std::nullopt;
        return mass[static_cast<std::size_t>(o.bodies[i])];
    };
    const PerBody<MassProperties> body_mass{mass_of(0), mass_of(1)};
    const PerBody<BodyMotion> motion = contact_motion(o.bodies, bodies);

    // Steps 1-5.
    const Basis contact_basis = basis(o.normal);
    const PerBody<Vec3> q_rel = relative_position(contact.point, {centre(0), centre(1)});
    const UnitImpulseChain chain = delta_velocity_per_unit_impulse(o.normal, q_rel, body_mass);
    const ContactVelocityTerms velocity =
        contact_velocity(contact_basis, q_rel, motion, settings.duration, settings.tangential_acceleration_velocity);
    const DesiredDeltaVelocity desired =
        desired_delta_velocity(velocity.contact_velocity.x(), contact.restitution, o.normal, motion, settings.duration,
                               velocity_refinements(settings), step_5_position_bias(contact.penetration, settings));

    // Built in one piece, every member from its value: a PreparedContact declared first and filled in after
    // would first clear its half kilobyte of optional per-body values, then overwrite them.
    return PreparedContact{.penetration = contact.penetration,
                           .contact_velocity = velocity.contact_velocity,
                           .desired_terms = desired,  // the bookkeeping starts from steps 4 and 5
                           .derivation = {.contact = index,
                                          .swapped = o.swapped,
                                          .bodies = o.bodies,
                                          .point = contact.point,
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
