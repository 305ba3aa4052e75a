#pragma once
// The engine's vocabulary types. Double precision throughout: the book's reference engine also compiles in
// double (its precision.h selects `typedef double real`), and a student comparing values digit by digit
// needs the extra digits.

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <array>
#include <optional>

namespace impulse {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;  // unit, rotating body space into world space; stored (x,y,z,w), written [w,x,y,z]

// A value per body of a contact: index 0 is body 0, index 1 is body 1, which is empty when body 1 is the
// static world. docs/design.md: "Per-body values are arrays [body0, body1], null for the world".
template <typename T>
using PerBody = std::array<std::optional<T>, 2>;

// Exact equality of the stored coefficients (Eigen defines none for quaternions), so plain structs holding
// an orientation can default their comparison.
inline bool operator==(const Quat& a, const Quat& b) {
    return a.coeffs() == b.coeffs();
}

// Sign of body i's share in a two-body contact: body 0 receives +impulse and moves along +normal,
// body 1 receives -impulse and moves along -normal.
constexpr double body_sign(int body_slot) {
    return body_slot == 0 ? 1.0 : -1.0;
}

}  // namespace impulse
