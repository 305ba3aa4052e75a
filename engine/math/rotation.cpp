#include "math/rotation.hpp"

#include <cmath>
#include <numbers>

namespace impulse {

Mat3 skew(const Vec3& r) {
    Mat3 m;
    m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
    return m;
}

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
    const Quat turn(Eigen::AngleAxisd(angle, rotation_vector / angle));
    return (turn * orientation).normalized();
}

double turned_angle(double magnitude, OrientationUpdate update) {
    // (1, theta/2) normalised has cos(a/2) = 1 / sqrt(1 + |theta|^2 / 4), so tan(a/2) = |theta| / 2.
    return update == OrientationUpdate::first_order ? 2.0 * std::atan(0.5 * magnitude) : magnitude;
}

double rotation_magnitude_for_angle(double angle, OrientationUpdate update) {
    return update == OrientationUpdate::first_order ? 2.0 * std::tan(0.5 * angle) : angle;
}

Quat orientation_from_euler_xyz_degrees(const Vec3& degrees) {
    const Vec3 radians = degrees * (std::numbers::pi / 180.0);
    const Quat qx(Eigen::AngleAxisd(radians.x(), Vec3::UnitX()));
    const Quat qy(Eigen::AngleAxisd(radians.y(), Vec3::UnitY()));
    const Quat qz(Eigen::AngleAxisd(radians.z(), Vec3::UnitZ()));
    return (qz * qy * qx).normalized();
}

}  // namespace impulse
