#include "methods/bookkeeping.hpp"

namespace impulse {

namespace {

// Calls visit(other, slot, m) for every candidate contact `other` whose body `slot` is the moved body `m`
// (0 or 1 of the resolved contact). The world never moves. A contact sharing both moved bodies is visited
// twice.
template <typename Indices, typename Visit>
void for_each_contact_sharing(std::vector<PreparedContact>& contacts, const Indices& candidates,
                              const std::array<int, 2>& moved, Visit visit) {
    for (const int index : candidates) {
        PreparedContact& other = contacts[static_cast<std::size_t>(index)];
        for (int slot = 0; slot < 2; ++slot) {
            const int body = other.derivation.bodies[slot];
            if (body == world_body) continue;
            for (int m = 0; m < 2; ++m)
                if (moved[m] == body) visit(other, slot, m);
        }
    }
}

// Every contact's index, 0 to count - 1, as a range-for walks it. Not std::views::iota: clang 14 cannot
// compile libstdc++ 12's <ranges>, and the fuzz preset (docs/fuzzing.md) builds the engine with clang.
struct ContactIndices {
    struct Iterator {
        int index;
        int operator*() const { return index; }
        Iterator& operator++() {
            ++index;
            return *this;
        }
        bool operator!=(const Iterator& other) const { return index != other.index; }
    };
    int count;
    Iterator begin() const { return {0}; }
    Iterator end() const { return {count}; }
};

ContactIndices every_contact(const std::vector<PreparedContact>& contacts) {
    return {static_cast<int>(contacts.size())};
}

template <typename Indices>
void update_penetrations_of(std::vector<PreparedContact>& contacts, const Indices& candidates,
                            const std::array<int, 2>& moved, const PositionChange& change,
                            std::vector<PenetrationUpdate>* log) {
    for_each_contact_sharing(contacts, candidates, moved, [&](PreparedContact& other, int slot, int m) {
        const ContactPreparation& d = other.derivation;
        // How far this contact's point on the moved body travelled along this contact's normal:
        // the translation plus the rotation's linear effect at the point, (dtheta x q_rel) . n.
        const Vec3 point_move = *change.linear_change[m] + change.angular_change[m]->cross(*d.relative_position[slot]);
        // Body 0 moving along +n opens the contact; body 1 moving along +n closes it.
        const double delta = -body_sign(slot) * point_move.dot(d.normal);
        const double before = other.penetration;
        other.penetration += delta;
        if (log) log->push_back({d.contact, moved[m], slot, delta, before, other.penetration});
    });
}

template <typename Indices>
void update_contact_velocities_of(std::vector<PreparedContact>& contacts, const Indices& candidates,
                                  const std::array<int, 2>& moved, const VelocityChange& change,
                                  const ResolverSettings& settings, std::vector<VelocityUpdate>* log) {
    const VelocityRefinements refinements = velocity_refinements(settings);
    for_each_contact_sharing(contacts, candidates, moved, [&](PreparedContact& other, int slot, int m) {
        const ContactPreparation& d = other.derivation;
        // The velocity change of this contact's point on the changed body (9.5), in its contact
        // coordinates, counted positive for body 0 and negative for body 1.
        const Vec3 point_change =
            *change.velocity_change[m] + change.rotation_change[m]->cross(*d.relative_position[slot]);
        const Vec3 delta = body_sign(slot) * to_contact(d.basis, point_change);
        const Vec3 before = other.contact_velocity;
        const double desired_before = other.desired_terms.desired_delta_velocity;
        other.contact_velocity += delta;
        // The reference engine re-runs step 5 on the partly resolved velocity, so the restitution cut-off is
        // judged again against the current closing speed. The restitution, the velocity from acceleration and
        // the position bias are the prepared ones, read from the bookkeeping's own step 5, which sits beside the
        // velocity in memory (the prepared step 5 is half a kilobyte away: one cache line fewer per update).
        const DesiredDeltaVelocity& step5 = other.desired_terms;
        other.desired_terms =
            desired_delta_velocity(other.contact_velocity.x(), step5.restitution, step5.velocity_from_acceleration,
                                   refinements, step5.position_bias);
        if (log)
            log->push_back({d.contact, moved[m], slot, delta, before, other.contact_velocity, desired_before,
                            other.desired_terms.desired_delta_velocity});
    });
}

}  // namespace

void update_penetrations(std::vector<PreparedContact>& contacts, std::span<const int> candidates,
                         const std::array<int, 2>& moved, const PositionChange& change,
                         std::vector<PenetrationUpdate>* log) {
    update_penetrations_of(contacts, candidates, moved, change, log);
}

void update_penetrations(std::vector<PreparedContact>& contacts, const std::array<int, 2>& moved,
                         const PositionChange& change, std::vector<PenetrationUpdate>* log) {
    update_penetrations_of(contacts, every_contact(contacts), moved, change, log);
}

void update_contact_velocities(std::vector<PreparedContact>& contacts, std::span<const int> candidates,
                               const std::array<int, 2>& moved, const VelocityChange& change,
                               const ResolverSettings& settings, std::vector<VelocityUpdate>* log) {
    update_contact_velocities_of(contacts, candidates, moved, change, settings, log);
}

void update_contact_velocities(std::vector<PreparedContact>& contacts, const std::array<int, 2>& moved,
                               const VelocityChange& change, const ResolverSettings& settings,
                               std::vector<VelocityUpdate>* log) {
    update_contact_velocities_of(contacts, every_contact(contacts), moved, change, settings, log);
}

}  // namespace impulse
