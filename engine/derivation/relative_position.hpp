#pragma once
// Step 2, `relative_position`: where the contact point sits relative to each body's origin,
// q_rel = q - p  (1.8). Every torque and point velocity of the chapter is built on it.

#include "math/types.hpp"

namespace impulse {

PerBody<Vec3> relative_position(const Vec3& contact_point, const PerBody<Vec3>& body_positions);

}  // namespace impulse
