#pragma once
// How values appear to a person: numbers with six significant digits, vectors in parentheses, matrices
// row by row, each with its unit. A value below `noise_fraction` of its scale (the largest magnitude shown
// beside it in the same unit: the vector's other components, the table's other values) is rounding noise
// and prints as 0; `exact` gives every digit, for a tooltip and for exports.

#include "math/types.hpp"

#include <string>
#include <string_view>

namespace impulse::explain {

// Values smaller than this share of their scale print as 0 (1.1e-16 beside 0.5 is rounding, not a value).
inline constexpr double noise_fraction = 1e-10;

// `scale`: the size of the values shown beside it in the same unit; 0 when there are none (only an exact 0
// prints as 0 then).
std::string number(double v, double scale = 0.0);
std::string vector(const Vec3& v, double scale = 0.0);       // scale: at least the vector's own largest part
std::string matrix_rows(const Mat3& m, double scale = 0.0);  // "[a, b, c]\n[d, e, f]\n[g, h, i]"
std::string quaternion(const Quat& q);                       // "[w, x, y, z]"

// Every digit (17 significant): the value as computed.
std::string exact(double v);
std::string exact(const Vec3& v);
std::string exact(const Mat3& m);

// A share in percent with three significant figures: "6.67", "33.3", "120".
std::string percent(double share);

// Appends " unit" unless the unit is empty.
std::string with_unit(std::string value, std::string_view unit);

}  // namespace impulse::explain
