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

// Throws unless |q| is 1 within unit_tolerance; returns q, normalised when it is off by more than rounding.
Quat unit_quaternion(const Quat& q, const std::string& path);

// Throws if n is zero; returns n normalised when it is off unit length by more than rounding.
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
