#include "preparation/bookkeeping.hpp"

namespace impulse {

ContactsByBody::ContactsByBody(std::span<const PreparedContact> contacts, std::size_t body_count)
    : first_(body_count + 1, 0) {
    // Count each body's contacts, turn the counts into starts, then place the contacts in index order.
    for (const PreparedContact& c : contacts)
        for (const int body : c.bodies)
            if (body != world_body) ++first_[static_cast<std::size_t>(body) + 1];
    for (std::size_t b = 0; b < body_count; ++b) first_[b + 1] += first_[b];
    contacts_.resize(static_cast<std::size_t>(first_[body_count]));
    std::vector<int> next(first_.begin(), first_.end() - 1);
    for (std::size_t i = 0; i < contacts.size(); ++i)
        for (const int body : contacts[i].bodies)
            if (body != world_body)
                contacts_[static_cast<std::size_t>(next[static_cast<std::size_t>(body)]++)] = static_cast<int>(i);
}

std::span<const int> ContactsByBody::contacts_of(int body) const {
    if (body == world_body) return {};
    const auto b = static_cast<std::size_t>(body);
    return std::span<const int>(contacts_).subspan(static_cast<std::size_t>(first_[b]),
                                                   static_cast<std::size_t>(first_[b + 1] - first_[b]));
}

void ContactsByBody::sharing(const std::array<int, 2>& moved, std::vector<int>& out) const {
    out.clear();
    const std::span<const int> a = contacts_of(moved[0]);
    const std::span<const int> b = moved[1] == moved[0] ? std::span<const int>() : contacts_of(moved[1]);
    // Both lists ascend: merge them, a contact on both bodies once.
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        int next;
        if (j == b.size() || (i < a.size() && a[i] < b[j]))
            next = a[i++];
        else if (i == a.size() || b[j] < a[i])
            next = b[j++];
        else
            next = a[i++], ++j;
        out.push_back(next);
    }
}

double penetration_change(const PreparedContact& contact, int slot, const Vec3& linear_change,
                          const Vec3& angular_change) {
    const Vec3 point_move = linear_change + cross(angular_change, contact.relative_position[slot]);
    return -body_sign(slot) * dot(point_move, contact.basis.normal());
}

Vec3 contact_velocity_change(const PreparedContact& contact, int slot, const Vec3& velocity_change,
                             const Vec3& rotation_change) {
    const Vec3 point_change = velocity_change + cross(rotation_change, contact.relative_position[slot]);
    return body_sign(slot) * to_contact(contact.basis, point_change);
}

DesiredDeltaVelocity desired_again(const PreparedContact& contact, const VelocityRefinements& refinements) {
    return desired_delta_velocity(contact.contact_velocity.x(), contact.restitution, contact.velocity_from_acceleration,
                                  refinements, contact.position_bias);
}

void update_penetrations(std::span<PreparedContact> contacts, std::span<const int> candidates,
                         const std::array<int, 2>& moved, const PositionChange& change) {
    for_each_sharing(contacts, candidates, moved, [&](int index, int slot, int m) {
        PreparedContact& other = contacts[static_cast<std::size_t>(index)];
        other.penetration += penetration_change(other, slot, *change.linear_change[m], *change.angular_change[m]);
    });
}

void update_contact_velocities(std::span<PreparedContact> contacts, std::span<const int> candidates,
                               const std::array<int, 2>& moved, const VelocityChange& change,
                               const VelocityRefinements& refinements) {
    for_each_sharing(contacts, candidates, moved, [&](int index, int slot, int m) {
        PreparedContact& other = contacts[static_cast<std::size_t>(index)];
        other.contact_velocity +=
            contact_velocity_change(other, slot, *change.velocity_change[m], *change.rotation_change[m]);
        other.desired_delta_velocity = desired_again(other, refinements).desired_delta_velocity;
    });
}

}  // namespace impulse
