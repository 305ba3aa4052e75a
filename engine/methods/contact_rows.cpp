#include "methods/contact_rows.hpp"

#include "methods/graph_colouring.hpp"

#include <cassert>
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

void fill_contact_row(ContactRow& row, const PreparedContact& d, const SolverBody* bodies, FrictionFill friction) {
    row.contact = d.contact;
    row.body = row_bodies(d);
    ContactMass mass{nullptr, nullptr};
    for (int i = 0; i < 2; ++i) {
        row.anchor[i] = d.relative_position[i];
        if (row.body[i] >= 0) mass[i] = &bodies[row.body[i]].mass;
    }
    row.basis = d.basis.contact_to_world;
    row.friction = friction == FrictionFill::none ? 0.0 : d.friction;
    // K_nn is step 3's d, so a rigid normal row visited alone gives the chapter's impulse g = v / d (14.3); the
    // friction rows read the rest of K (derivation/impulse.hpp), as the book's friction solve does.
    const double k_nn = d.delta_velocity_per_unit_impulse;
    row.normal_response = k_nn;
    row.normal_mass = 1.0 / k_nn;
    if (row.friction != 0.0 && friction == FrictionFill::rows) {
        const FrictionMatrixOf<double> f = friction_matrix<double>(delta_velocity_matrix(d.basis, row.anchor, mass));
        row.normal_to_tangent = f.normal_to_tangent;
        row.tangent_response = f.tangent_response;
        row.tangent_mass = f.tangent_mass;
        row.tangent_invertible = f.tangent_invertible;
    }
}

RowSolver::RowSolver(FrameContext& frame, bool in_colours, bool with_rows)
    : frame_(frame),
      settings_(frame.settings),
      bodies_(solver_bodies(frame.bodies, frame.mass, frame.scratch)),
      moving_(frame.scratch),
      slots_(frame.scratch),
      order_(frame.scratch),
      keys_(frame.scratch),
      kept_(frame.scratch),
      colours_(frame.scratch),
      pairs_(frame.scratch) {
    moving_.reserve(frame.contacts.size());
    keys_.reserve(frame.contacts.size());
    if (in_colours) pairs_.reserve(frame.contacts.size());
    for (std::size_t c = 0; c < frame.contacts.size(); ++c) {
        // What this loop reads of a contact (its identity and step 3's d, the start of each 272 bytes), asked for
        // 16 contacts ahead: each iteration is short, and each contact a cache miss.
        if (c + 16 < frame.contacts.size())
            fetch_ahead(frame.contacts[c + 16].contact, frame.contacts[c + 16].delta_velocity_per_unit_impulse);
        assert(frame.contacts[c].contact == static_cast<int>(c) && "prepared in the input's order (stamp's indices)");
        if (!can_move(frame.contacts[c])) continue;
        moving_.push_back(static_cast<std::uint32_t>(c));
        keys_.push_back(contact_key(frame.contacts[c]));
        if (in_colours) pairs_.push_back(row_bodies(frame.contacts[c]));
    }
    const std::size_t count = moving_.size();
    if (in_colours) {
        colours_ = pair_colours(pairs_, bodies_, frame.scratch);
        slots_ = slots_of_colours(colours_, frame.scratch);
    } else {
        slots_.resize(count);
        for (std::size_t k = 0; k < count; ++k) slots_[k] = static_cast<std::uint32_t>(k);
    }
    order_.resize(count);
    for (std::size_t k = 0; k < count; ++k) order_[slots_[k]] = static_cast<std::uint32_t>(k);
    if (with_rows)
        rows_ = {static_cast<ContactRow*>(frame.scratch->allocate(count * sizeof(ContactRow), alignof(ContactRow))),
                 count};
    if (frame.keeping) kept_.resize(count);
}

RowSolver::~RowSolver() {
    static_assert(std::is_trivially_destructible_v<ContactRow>);
    if (rows_.data())  // allocated (with_rows), if for no row
        frame_.scratch->deallocate(rows_.data(), rows_.size() * sizeof(ContactRow), alignof(ContactRow));
}

std::optional<RowVisit> RememberedTotals::of(const Mat3& basis, double friction, const ContactKey& key) {
    if (memory_.size() == 0) return std::nullopt;
    const std::ptrdiff_t slot = memory_.slot_of(key, next_);
    if (slot < 0 || taken_[static_cast<std::size_t>(slot)]) return std::nullopt;
    next_ = slot + 1;
    taken_[static_cast<std::size_t>(slot)] = 1;
    const Vec3 total = to_contact(basis, memory_.impulse_at(slot));  // C^T g: the world's g in this frame's basis
    RowVisit v;
    v.unclamped = v.after = {total.x(), total.y(), total.z()};
    v.pushed_only = total.x() < 0.0;
    if (v.pushed_only) v.after.n = 0.0;
    const double limit = friction * v.after.n;
    const double tangential = v.after.t1 * v.after.t1 + v.after.t2 * v.after.t2;
    v.sliding = tangential > limit * limit;
    if (v.sliding) {
        const double scale = tangential > 0.0 ? limit / std::sqrt(tangential) : 0.0;
        v.after.t1 *= scale;
        v.after.t2 *= scale;
    }
    return v;
}

}  // namespace impulse
