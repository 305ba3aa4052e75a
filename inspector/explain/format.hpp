#pragma once
// How values appear to a person: numbers with six significant digits, vectors in parentheses, matrices
// row by row, each with its unit.

#include "math/types.hpp"

#include <string>
#include <string_view>

namespace impulse::explain {

std::string number(double v);
std::string vector(const Vec3& v);
std::string matrix_rows(const Mat3& m);  // "[a, b, c]\n[d, e, f]\n[g, h, i]"
std::string quaternion(const Quat& q);   // "[w, x, y, z]"

// Appends " unit" unless the unit is empty.
std::string with_unit(std::string value, std::string_view unit);

}  // namespace impulse::explain
