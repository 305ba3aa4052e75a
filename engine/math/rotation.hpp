#pragma once
// Rotations: orientation updates from a rotation vector, and the
// conversions a person needs to write an orientation down.

#include "math/types.hpp"

namespace impulse {

// How an orientation is turned by a small rotation vector theta (axis * angle, world frame).
enum class OrientationUpdate {
    first_order,  // q += 1/2 (0, theta) q, then normalise: the reference engine's update
    exact,        // q = exp(theta / 2) q: turns by exactly |theta| radians
};

Quat rotated(const Quat& orientation, const Vec3& rotation_vector, OrientationUpdate update);

// The angle (radians) that `rotated` actually turns through for a rotation vector of length `magnitude`.
// first_order + normalise turns through 2 atan(|theta| / 2), slightly less than |theta|.
double turned_angle(double magnitude, OrientationUpdate update);

// The inverse of turned_angle: the rotation-vector length that turns through exactly `angle` radians.
double rotation_magnitude_for_angle(double angle, OrientationUpdate update);

// Orientation from XYZ Euler angles in degrees: rotate about world X first, then world Y, then world Z,
// i.e. R = Rz * Ry * Rx.
Quat orientation_from_euler_xyz_degrees(const Vec3& degrees);

}  // namespace impulse
