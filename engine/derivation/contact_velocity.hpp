#pragma once
// Step 4, `contact_velocity`: the velocity of body 0's contact point relative to body 1's, in contact
// coordinates. Its x component is the chapter's separating velocity v_s (negative = closing); y and z are
// the sliding speeds that friction works on.

#include "derivation/basis.hpp"
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

ContactVelocityTerms contact_velocity(const Basis& basis, const PerBody<Vec3>& relative_position,
                                      const PerBody<BodyMotion>& motion, double duration,
                                      bool tangential_acceleration_velocity);

}  // namespace impulse
