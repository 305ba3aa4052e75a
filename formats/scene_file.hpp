#pragma once
// Scene files (docs/scenes.md): bodies with shapes (or, in a case, without them), materials, the ground,
// gravity, explicit contacts and settings. Reading checks the schema first (types, ranges, unknown and
// missing fields), then what a schema cannot say (names, references, unit quaternions and normals,
// symmetric positive definite inertia), each error naming its JSON path.

#include "formats/json_values.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace impulse::formats {

Scene read_scene(const json& document, const std::optional<std::string>& preset_override = std::nullopt);
Scene read_scene_text(std::string_view text, const std::optional<std::string>& preset_override = std::nullopt);

// The scene in its fully specified form: every default filled in, every body with its inverse mass and
// body-space inverse inertia (so it reproduces a run to the last bit), contacts by body name. Settings only
// when asked for (a trace keeps them in its header).
json scene_json(const Scene& scene, bool with_settings);

}  // namespace impulse::formats
