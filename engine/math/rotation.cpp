#include "math/rotation.hpp"

#include "math/elementary.hpp"

#include <numbers>

namespace impulse {

namespace {

// The turn by `angle` radians about the unit `axis`: (cos(angle/2), sin(angle/2) axis), as Eigen's AngleAxis gives
// it, with the engine's own sine and cosine (math/elementary.hpp).
Quat turn(double angle, const Vec3& axis) {
    const elementary::SinCos half = elementary::sin_cos(0.5 * angle);
    return Quat(half.cos, half.sin * axis.x(), half.sin * axis.y(), half.sin * axis.z());
}

}  // namespace

Quat rotated(const Quat& orientation, const Vec3& rotation_vector, OrientationUpdate update) {
    if (update == OrientationUpdate::first_order) {
        // q' = q + 1/2 (0, theta) q: the derivative dq/dt = 1/2 w q integrated over one unit of time.
        const Quat spin(0.0, rotation_vector.x(), rotation_vector.y(), rotation_vector.z());
        Quat q = spin * orientation;
        q.coeffs() = orientation.coeffs() + 0.5 * q.coeffs();
        return q.normalized();
    }
    const double angle = rotation_vector.norm();
    if (angle == 0.0) return orientation;
    return (turn(angle, rotation_vector / angle) * orientation).normalized();
}

double turned_angle(double magnitude, OrientationUpdate update) {
    // (1, theta/2) normalised has cos(a/2) = 1 / sqrt(1 + |theta|^2 / 4), so tan(a/2) = |theta| / 2.
    return update == OrientationUpdate::first_order ? 2.0 * elementary::atan(0.5 * magnitude) : magnitude;
}

double rotation_magnitude_for_angle(double angle, OrientationUpdate update) {
    return update == OrientationUpdate::first_order ? 2.0 * elementary::tan(0.5 * angle) : angle;
}

Quat orientation_from_euler_xyz_degrees(const Vec3& degrees) {
    const Vec3 radians = degrees * (std::numbers::pi / 180.0);
    return (turn(radians.z(), Vec3::UnitZ()) * turn(radians.y(), Vec3::UnitY()) * turn(radians.x(), Vec3::UnitX()))
        .normalized();
}

}  // namespace impulse
