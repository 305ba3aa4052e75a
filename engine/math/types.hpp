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
// A body's six degrees of freedom together, (linear x, y, z, angular x, y, z): AVBD's per-body block.
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

// A value per body of a contact: index 0 is body 0, index 1 is body 1, which is empty when body 1 is the
// static world. docs/design.md: "Per-body values are arrays [body0, body1], null for the world".
template <typename T>
using PerBody = std::array<std::optional<T>, 2>;

// The value per body that `make(i)` computes for each body that `present` says is there, empty for the others,
// built in one go. (An empty std::optional clears all of its storage, so a PerBody declared empty and filled in
// afterwards would clear every value's bytes first; for the larger values that is a visible cost.)
template <typename Make>
auto per_body(const std::array<bool, 2>& present, Make make) -> PerBody<decltype(make(0))> {
    using T = decltype(make(0));
    return {present[0] ? std::optional<T>(make(0)) : std::nullopt,
            present[1] ? std::optional<T>(make(1)) : std::nullopt};
}

template <typename T>
std::array<bool, 2> present(const PerBody<T>& values) {
    return {values[0].has_value(), values[1].has_value()};
}

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
