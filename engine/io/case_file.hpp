#pragma once
// Case files: bodies without shapes plus explicit contacts (docs/case-files.md). Reading checks the schema
// first (types, ranges, unknown and missing fields), then what a schema cannot say (names, references,
// unit quaternions and normals, symmetric positive definite inertia), each error naming its JSON path.

#include "io/json_values.hpp"
#include "scene/case.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace impulse::io {

Case read_case(const json& document, const std::optional<std::string>& preset_override = std::nullopt);
Case read_case_text(std::string_view text, const std::optional<std::string>& preset_override = std::nullopt);

// The case in its fully specified form: every body with its inverse mass and body-space inverse inertia
// (so it reproduces the run to the last bit), contacts by body name. Settings only when asked for.
json case_json(const Case& c, bool with_settings);

// The inertia of a solid shape of mass m, as its inverse (body space):
// sphere 2/5 m r^2; box with half-sizes (a, b, c): m (b^2 + c^2) / 3 about x, and so on.
Mat3 sphere_inverse_inertia(double inverse_mass, double radius);
Mat3 box_inverse_inertia(double inverse_mass, const Vec3& half_size);

}  // namespace impulse::io
