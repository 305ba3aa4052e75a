#include "methods/contact_rows.hpp"

#include "methods/solver_common.hpp"

namespace impulse {

std::pmr::vector<SolverBody> solver_bodies(std::span<const RigidBody> bodies, std::span<const MassProperties> mass,
                                           std::pmr::memory_resource* memory) {
    std::pmr::vector<SolverBody> solver(bodies.size(), memory);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        solver[b].velocity = bodies[b].velocity;
        solver[b].angular_velocity = bodies[b].angular_velocity;
        solver[b].inverse_mass = mass[b].inverse_mass;
        solver[b].inverse_inertia = mass[b].inverse_inertia_world;
    }
    return solver;
}

void store_velocities(std::span<const SolverBody> solver, std::vector<RigidBody>& bodies) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        bodies[b].velocity = solver[b].velocity;
        bodies[b].angular_velocity = solver[b].angular_velocity;
    }
}

bool fill_contact_row(ContactRow& row, const RowPreparation& d, const SolverBody* bodies, bool friction_rows) {
    row.contact = d.contact;
    for (int i = 0; i < 2; ++i) {
        row.body[i] = d.bodies[i] == world_body ? -1 : d.bodies[i];
        row.anchor[i] = d.relative_position[i];
    }
    row.normal = d.basis.normal;
    row.tangent1 = d.basis.tangent1;
    row.tangent2 = d.basis.tangent2;
    row.friction = friction_rows ? d.friction : 0.0;
    const bool tangents = row.friction != 0.0;
    // K_ab = sum over bodies of m^-1 (a . b) + (r x a) . I^-1 (r x b): derivation/impulse.hpp's
    // delta_velocity_matrix entry by entry (C^T (m^-1 1 - [r]x I^-1 [r]x) C), for the entries the rows need: K_nn
    // always, the friction rows' four with friction. K_nn is step 3's d up to rounding ((I^-1 u) x r . n and
    // u . I^-1 u with u = r x n are the same triple product); the rows take it from here, where the friction
    // entries come from, so the rows need nothing of step 3's record.
    double k_nn = 0.0, k_1n = 0.0, k_2n = 0.0, k_11 = 0.0, k_12 = 0.0, k_22 = 0.0;
    const Vec3 &n = row.normal, &t1 = row.tangent1, &t2 = row.tangent2;
    const double linear_nn = n.dot(n);                                                  // 1 up to rounding
    const double linear_1n = t1.dot(n), linear_2n = t2.dot(n), linear_12 = t1.dot(t2);  // 0 up to rounding
    for (int i = 0; i < 2; ++i) {
        if (row.body[i] < 0) continue;
        const SolverBody& m = bodies[row.body[i]];
        const Vec3& r = row.anchor[i];
        const Mat3& inertia = m.inverse_inertia;
        // u_a = r x a and I^-1 u_a (written out: the row's other functions keep to plain doubles too). I^-1 is
        // symmetric, so (r x a) . I^-1 (r x b) = (r x b) . I^-1 (r x a): one product per axis serves all.
        const double unx = r.y() * n.z() - r.z() * n.y(), uny = r.z() * n.x() - r.x() * n.z(),
                     unz = r.x() * n.y() - r.y() * n.x();
        const double jnx = inertia(0, 0) * unx + inertia(0, 1) * uny + inertia(0, 2) * unz,
                     jny = inertia(1, 0) * unx + inertia(1, 1) * uny + inertia(1, 2) * unz,
                     jnz = inertia(2, 0) * unx + inertia(2, 1) * uny + inertia(2, 2) * unz;
        k_nn += m.inverse_mass * linear_nn + (unx * jnx + uny * jny + unz * jnz);
        if (!tangents) continue;
        const double u1x = r.y() * t1.z() - r.z() * t1.y(), u1y = r.z() * t1.x() - r.x() * t1.z(),
                     u1z = r.x() * t1.y() - r.y() * t1.x();
        const double u2x = r.y() * t2.z() - r.z() * t2.y(), u2y = r.z() * t2.x() - r.x() * t2.z(),
                     u2z = r.x() * t2.y() - r.y() * t2.x();
        const double j1x = inertia(0, 0) * u1x + inertia(0, 1) * u1y + inertia(0, 2) * u1z,
                     j1y = inertia(1, 0) * u1x + inertia(1, 1) * u1y + inertia(1, 2) * u1z,
                     j1z = inertia(2, 0) * u1x + inertia(2, 1) * u1y + inertia(2, 2) * u1z;
        const double j2x = inertia(0, 0) * u2x + inertia(0, 1) * u2y + inertia(0, 2) * u2z,
                     j2y = inertia(1, 0) * u2x + inertia(1, 1) * u2y + inertia(1, 2) * u2z,
                     j2z = inertia(2, 0) * u2x + inertia(2, 1) * u2y + inertia(2, 2) * u2z;
        k_1n += m.inverse_mass * linear_1n + (unx * j1x + uny * j1y + unz * j1z);
        k_2n += m.inverse_mass * linear_2n + (unx * j2x + uny * j2y + unz * j2z);
        k_11 += m.inverse_mass + (u1x * j1x + u1y * j1y + u1z * j1z);
        k_12 += m.inverse_mass * linear_12 + (u1x * j2x + u1y * j2y + u1z * j2z);
        k_22 += m.inverse_mass + (u2x * j2x + u2y * j2y + u2z * j2z);
    }
    row.normal_response = k_nn;  // d (step 3)
    row.normal_mass = 1.0 / k_nn;
    if (tangents) {
        row.normal_to_tangent = {k_1n, k_2n};
        row.tangent_response = {k_11, k_12, k_22};
        const double det = k_11 * k_22 - k_12 * k_12;
        row.tangent_invertible = det > 0.0;
        if (row.tangent_invertible) {
            const double inverse_det = 1.0 / det;
            row.tangent_mass = {k_22 * inverse_det, -k_12 * inverse_det, k_11 * inverse_det};
        } else {
            // Singular (a body that turns about one axis only): solve each tangent row on its own.
            row.tangent_mass = {k_11 > 0.0 ? 1.0 / k_11 : 0.0, 0.0, k_22 > 0.0 ? 1.0 / k_22 : 0.0};
        }
    }
    return k_nn > 0.0;
}

ActiveRows::ActiveRows(std::size_t capacity, std::pmr::memory_resource* scratch)
    : rows(scratch), contacts(scratch), keys(scratch) {
    rows.reserve(capacity);
    contacts.reserve(capacity);
    keys.reserve(capacity);
}

ContactRow* ActiveRows::add(const RowPreparation& contact, const SolverBody* bodies) {
    if (!fill_contact_row(rows.emplace_back(), contact, bodies)) {
        rows.pop_back();
        return nullptr;
    }
    contacts.push_back(contact.contact);
    keys.push_back(contact_key(contact));
    return &rows.back();
}

std::optional<RowVisit> RememberedTotals::of(const ContactRow& row, const ContactKey& key) {
    if (memory_.size() == 0) return std::nullopt;
    const std::ptrdiff_t slot = memory_.slot_of(key, next_);
    if (slot < 0 || taken_[static_cast<std::size_t>(slot)]) return std::nullopt;
    next_ = slot + 1;
    taken_[static_cast<std::size_t>(slot)] = 1;
    const Vec3& g = memory_.impulse_at(slot);  // world; C^T g in this frame's basis
    return within_limits({row.normal.dot(g), row.tangent1.dot(g), row.tangent2.dot(g)}, row.friction);
}

void remember_totals(std::span<const ContactRow> rows, std::span<const ContactKey> keys, ContactMemory& memory) {
    memory.remember(keys, [&](std::size_t r) { return world_impulse(rows[r], rows[r].total_impulse); });
}

}  // namespace impulse
