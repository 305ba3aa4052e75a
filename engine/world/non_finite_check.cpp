#include "world/non_finite_check.hpp"

namespace impulse {

namespace {

const char* non_finite_quantity(const RigidBody& body) {
    if (!body.position.allFinite()) return "position";
    if (!body.orientation.coeffs().allFinite()) return "orientation";
    if (!body.velocity.allFinite()) return "velocity";
    if (!body.angular_velocity.allFinite()) return "angular velocity";
    return nullptr;
}

}  // namespace

std::optional<NonFiniteBody> first_non_finite(std::span<const RigidBody> bodies) {
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (const char* quantity = non_finite_quantity(bodies[i]))
            return NonFiniteBody{.body = static_cast<int>(i),
                                 .quantity = quantity,
                                 .last_contact = std::nullopt,
                                 .last_contact_bodies = {0, world_body}};
    return std::nullopt;
}

std::optional<NonFiniteBody> first_non_finite(std::span<const RigidBody> bodies, const LastTouch& touch) {
    std::optional<NonFiniteBody> broken = first_non_finite(bodies);
    if (broken) {
        broken->last_contact = touch.last_contact(broken->body);
        if (broken->last_contact) broken->last_contact_bodies = touch.bodies_of(*broken->last_contact);
    }
    return broken;
}

}  // namespace impulse
