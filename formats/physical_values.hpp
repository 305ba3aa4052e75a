#pragma once
// What a file's numbers must be to describe a body or a contact, beyond their types: unit quaternions and
// normals, symmetric inertia that is positive definite (or semi-definite for its inverse: zero cannot turn),
// orthonormal contact bases. Each check throws InputError(path, problem) naming what is wrong and by how much.

#include "math/types.hpp"

#include <string>

namespace impulse::formats {

// A stored quaternion or normal is used as it is when it is unit to rounding, so a file written by us reads
// back bit for bit; a quaternion further than this from unit length is refused rather than normalised.
inline constexpr double unit_rounding = 1e-12;
inline constexpr double unit_tolerance = 1e-6;

// The ranges in which the values a contact's preparation multiplies together stay finite, normal doubles. A
// body's inverse inertia is m⁻¹/r² (5/2 m⁻¹/r² for a sphere), a contact's response to a unit impulse
// (I⁻¹(q × n)) × q: with masses and sizes from 1e-30 to 1e30 and lengths up to 1e30, every such product is
// between about 1e-150 and 1e150. A mass of 1e-320 (m⁻¹ infinite), a radius of 1e-200 (r² = 0) or a normal
// [1e308, 1e308, 0] (its length infinite) made a run record values its own trace reader refuses, or lose a
// contact. Velocities and accelerations are not bounded here: a run whose motion overflows stops at that frame
// with the frames before it written (exit code 3).
inline constexpr double smallest_size = 1e-30;  // kg, m: a mass, a radius, a half size, an inverse mass
inline constexpr double largest_size = 1e30;
inline constexpr double largest_length = 1e30;  // m: a coordinate, a penetration, a plane's offset
inline constexpr double smallest_inertia = 1e-90, largest_inertia = 1e90;  // an entry of I or I⁻¹ that is not 0

// Throws unless `value` is a size, from smallest_size to largest_size ("must be from 1e-30 to 1e30 ...").
double require_size(double value, const std::string& path);
// Throws unless `value` is 0 or a size (an inverse mass: 0 is immovable).
double require_size_or_zero(double value, const std::string& path);
// Throws unless every component is at most largest_length in size.
Vec3 require_lengths(const Vec3& v, const std::string& path);
// Throws unless every entry is 0 or between smallest_inertia and largest_inertia in size.
void require_inertia_entries(const Mat3& m, const std::string& path);

// Throws unless |q| is 1 within unit_tolerance; returns q, normalised when it is off by more than rounding.
Quat unit_quaternion(const Quat& q, const std::string& path);

// Throws if n is zero or a component is larger than largest_length; returns n normalised when it is off unit
// length by more than rounding.
Vec3 nonzero_direction(const Vec3& n, const std::string& path);

// Throws unless |n| is 1 within unit_tolerance (a recorded normal or basis column).
void require_unit_vector(const Vec3& n, const std::string& path);

// Throws unless the columns are unit and at right angles within unit_tolerance.
void require_orthonormal(const Mat3& m, const std::string& path);

void require_symmetric(const Mat3& m, const std::string& path);

// The inverse of a symmetric positive definite inertia tensor; throws with its eigenvalues otherwise.
Mat3 inverse_of_inertia(const Mat3& inertia, const std::string& path);

// Throws unless symmetric positive semi-definite (all zero: the body cannot turn).
void check_inverse_inertia(const Mat3& inverse_inertia, const std::string& path);

}  // namespace impulse::formats
