#pragma once
// Step 4, `contact_velocity`: the velocity of body 0's contact point relative to body 1's, in contact
// coordinates. Its x component is the chapter's separating velocity v_s (negative = closing); y and z are
// the sliding speeds that friction works on.

#include "derivation/basis.hpp"
#include "math/lanes.hpp"
#include "math/products.hpp"
#include "math/types.hpp"

namespace impulse {

// What the step needs of one body's motion.
struct BodyMotion {
    Vec3 velocity = Vec3::Zero();
    Vec3 angular_velocity = Vec3::Zero();
    Vec3 last_frame_acceleration = Vec3::Zero();

    bool operator==(const BodyMotion&) const = default;
};

struct ContactVelocityTerms {
    PerBody<Vec3> point_velocity;  // theta-dot x q_rel + p-dot, world  (9.5)
    // The reference engine's chapter-15 term: the tangential part of (last frame's acceleration x duration),
    // in contact coordinates, normal part zeroed. Sliding caused by this frame's forces is then left for
    // friction to remove. Empty per body when the setting is off.
    PerBody<Vec3> tangential_acceleration_velocity;
    Vec3 contact_velocity;  // (point velocity 0 + term 0) - (point velocity 1 + term 1), contact coordinates

    bool operator==(const ContactVelocityTerms&) const = default;
};

// A body's point velocity at q_rel from its centre, theta-dot x q_rel + p-dot  (9.5), world. Inline, in plain
// doubles (math/products.hpp): the book's step 4 and every accumulating method's rows read velocities through it.
// Over a Vec3, or a Vec3x4 (math/lanes.hpp: four pairs of a wide record).
template <typename V>
IMPULSE_KERNEL V point_velocity_of(const V& velocity, const V& angular_velocity, const V& relative_position) {
    const V turning = cross(angular_velocity, relative_position);
    return {turning.x() + velocity.x(), turning.y() + velocity.y(), turning.z() + velocity.z()};
}

IMPULSE_KERNEL Vec3 point_velocity(const Vec3& velocity, const Vec3& angular_velocity, const Vec3& relative_position) {
    return point_velocity_of<Vec3>(velocity, angular_velocity, relative_position);
}

// One body's share of step 4: its point velocity, and with the refinement its tangential acceleration term, both
// in contact coordinates (the term's normal part zeroed), and their sum, which the contact velocity adds for body 0
// and subtracts for body 1. Every preparation and the recorder compute step 4 through it.
struct BodyContactVelocity {
    Vec3 point_velocity;                    // world (9.5)
    Vec3 tangential_acceleration_velocity;  // contact coordinates; zero with the refinement off
    Vec3 local;                             // point velocity in contact coordinates plus that term
};
IMPULSE_KERNEL BodyContactVelocity body_contact_velocity(const Mat3& contact_to_world, const Vec3& relative_position,
                                                         const BodyMotion& motion, double duration,
                                                         bool tangential_acceleration_velocity) {
    BodyContactVelocity v;
    v.point_velocity = point_velocity(motion.velocity, motion.angular_velocity, relative_position);
    v.local = to_contact(contact_to_world, v.point_velocity);
    v.tangential_acceleration_velocity = Vec3::Zero();
    if (tangential_acceleration_velocity) {
        v.tangential_acceleration_velocity = to_contact(contact_to_world, motion.last_frame_acceleration * duration);
        // Only the sliding part; the normal part is for restitution (step 5).
        v.tangential_acceleration_velocity.x() = 0.0;
        v.local += v.tangential_acceleration_velocity;
    }
    return v;
}

ContactVelocityTerms contact_velocity(const Basis& basis, const PerBody<Vec3>& relative_position,
                                      const PerBody<BodyMotion>& motion, double duration,
                                      bool tangential_acceleration_velocity);

}  // namespace impulse
