#include "methods/contact_rows.hpp"

#include "derivation/impulse.hpp"
#include "methods/solver_common.hpp"

#include <unordered_set>

namespace impulse {

std::vector<SolverBody> solver_bodies(std::span<const RigidBody> bodies, std::span<const PreparedContact> contacts) {
    std::vector<SolverBody> solver(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        solver[b].velocity = bodies[b].velocity;
        solver[b].angular_velocity = bodies[b].angular_velocity;
    }
    // The mass as the contacts were prepared with (mass_properties: the world inverse inertia of the frame).
    for (const PreparedContact& c : contacts)
        for (int i = 0; i < 2; ++i)
            if (c.mass[i]) {
                SolverBody& body = solver[static_cast<std::size_t>(c.derivation.bodies[i])];
                body.inverse_mass = c.mass[i]->inverse_mass;
                body.inverse_inertia = c.mass[i]->inverse_inertia_world;
            }
    return solver;
}

void store_velocities(std::span<const SolverBody> solver, std::vector<RigidBody>& bodies) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        bodies[b].velocity = solver[b].velocity;
        bodies[b].angular_velocity = solver[b].angular_velocity;
    }
}

ContactRow contact_row(int index, const PreparedContact& contact, bool friction_rows) {
    const ContactPreparation& d = contact.derivation;
    ContactRow row;
    row.contact = index;
    for (int i = 0; i < 2; ++i) {
        row.body[i] = d.bodies[i] == world_body ? -1 : d.bodies[i];
        row.anchor[i] = d.relative_position[i] ? *d.relative_position[i] : Vec3::Zero();
    }
    row.normal = d.basis.normal;
    row.tangent1 = d.basis.tangent1;
    row.tangent2 = d.basis.tangent2;
    row.normal_mass = 1.0 / d.velocity_per_unit_impulse.delta_velocity_per_unit_impulse;  // 1 / d
    row.friction = friction_rows ? d.friction : 0.0;
    if (row.friction != 0.0) {
        const Mat3 k = delta_velocity_matrix(d.basis, d.relative_position, contact.mass);
        row.normal_to_tangent = k.block<2, 1>(1, 0);
        row.tangent_response = k.block<2, 2>(1, 1);
        row.tangent_invertible = row.tangent_response.determinant() > 0.0;
        if (row.tangent_invertible) {
            row.tangent_mass = row.tangent_response.inverse();
        } else {
            // Singular (a body that turns about one axis only): solve each tangent row on its own.
            for (int t = 0; t < 2; ++t)
                if (row.tangent_response(t, t) > 0.0) row.tangent_mass(t, t) = 1.0 / row.tangent_response(t, t);
        }
    }
    return row;
}

std::vector<std::optional<AccumulatedImpulse>> remembered_totals(std::span<const ContactRow> rows,
                                                                 std::span<const PreparedContact> contacts,
                                                                 const ContactMemory& memory) {
    std::vector<std::optional<AccumulatedImpulse>> totals(rows.size());
    if (memory.size() == 0) return totals;
    std::unordered_set<ContactKey, ContactKeyHash> seen;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const ContactPreparation& d = contacts[static_cast<std::size_t>(rows[r].contact)].derivation;
        const ContactKey key = contact_key(d);
        if (!seen.insert(key).second) continue;
        if (const std::optional<Vec3> remembered = memory.recall(key))
            totals[r] = within_limits(to_contact(d.basis, *remembered), d.friction);
    }
    return totals;
}

void remember_totals(std::span<const ContactRow> rows, std::span<const PreparedContact> contacts,
                     ContactMemory& memory) {
    std::vector<std::pair<ContactKey, Vec3>> totals;
    totals.reserve(rows.size());
    for (const ContactRow& row : rows)
        totals.emplace_back(contact_key(contacts[static_cast<std::size_t>(row.contact)].derivation),
                            world_impulse(row, row.total_impulse));
    memory.remember(totals);
}

}  // namespace impulse
