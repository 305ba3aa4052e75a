#include "methods/contact_rows.hpp"

#include <new>
#include <type_traits>

namespace impulse {

std::pmr::vector<SolverBody> solver_bodies(std::span<const RigidBody> bodies, std::span<const MassProperties> mass,
                                           std::pmr::memory_resource* memory) {
    std::pmr::vector<SolverBody> solver(bodies.size(), memory);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        solver[b].velocity = bodies[b].velocity;
        solver[b].angular_velocity = bodies[b].angular_velocity;
        solver[b].mass = mass[b];
    }
    return solver;
}

void store_velocities(std::span<const SolverBody> solver, std::vector<RigidBody>& bodies) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        bodies[b].velocity = solver[b].velocity;
        bodies[b].angular_velocity = solver[b].angular_velocity;
    }
}

void fill_contact_row(ContactRow& row, const PreparedContact& d, const SolverBody* bodies, bool friction_rows) {
    row.contact = d.contact;
    row.body = row_bodies(d);
    ContactMass mass{nullptr, nullptr};
    for (int i = 0; i < 2; ++i) {
        row.anchor[i] = d.relative_position[i];
        if (row.body[i] >= 0) mass[i] = &bodies[row.body[i]].mass;
    }
    row.basis = d.basis.contact_to_world;
    row.friction = friction_rows ? d.friction : 0.0;
    // K_nn is step 3's d, so a rigid normal row visited alone gives the chapter's impulse g = v / d (14.3); the
    // friction rows read the rest of K (derivation/impulse.hpp), as the book's friction solve does.
    const double k_nn = d.delta_velocity_per_unit_impulse;
    row.normal_response = k_nn;
    row.normal_mass = 1.0 / k_nn;
    if (row.friction != 0.0) {
        const Mat3 k = delta_velocity_matrix(d.basis, row.anchor, mass);
        const double k_11 = k(1, 1), k_12 = k(1, 2), k_22 = k(2, 2);
        row.normal_to_tangent = {k(1, 0), k(2, 0)};
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
}

PlacedRows::PlacedRows(std::size_t count, std::pmr::memory_resource* scratch)
    : rows(static_cast<ContactRow*>(scratch->allocate(count * sizeof(ContactRow), alignof(ContactRow))), count),
      scratch_(scratch) {}

PlacedRows::~PlacedRows() {
    static_assert(std::is_trivially_destructible_v<ContactRow>);
    scratch_->deallocate(rows.data(), rows.size() * sizeof(ContactRow), alignof(ContactRow));
}

void PlacedRows::place(std::size_t slot, const PreparedContact& contact, const SolverBody* bodies) {
    ContactRow* row = new (rows.data() + slot) ContactRow;  // the slot's row begins here
    fill_contact_row(*row, contact, bodies);
}

std::optional<RowVisit> RememberedTotals::of(const ContactRow& row, const ContactKey& key) {
    if (memory_.size() == 0) return std::nullopt;
    const std::ptrdiff_t slot = memory_.slot_of(key, next_);
    if (slot < 0 || taken_[static_cast<std::size_t>(slot)]) return std::nullopt;
    next_ = slot + 1;
    taken_[static_cast<std::size_t>(slot)] = 1;
    const Vec3& g = memory_.impulse_at(slot);  // world; C^T g in this frame's basis
    return within_limits(to_contact(row.basis, g), row.friction);
}

void remember_totals(std::span<const ContactRow> rows, std::span<const ContactKey> keys, ContactMemory& memory) {
    memory.remember(keys, [&](std::size_t r) { return world_impulse(rows[r], rows[r].total_impulse); });
}

}  // namespace impulse
