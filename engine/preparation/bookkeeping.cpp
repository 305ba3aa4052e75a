#include "preparation/bookkeeping.hpp"

namespace impulse {

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

template void update_penetrations(std::span<PreparedContact>, std::span<const int>, const std::array<int, 2>&,
                                  const PositionChange&, NotShown);
template void update_contact_velocities(std::span<PreparedContact>, std::span<const int>, const std::array<int, 2>&,
                                        const VelocityChange&, const VelocityRefinements&, NotShown);

}  // namespace impulse
