#pragma once
// Scene files (docs/scenes.md): bodies with shapes (or, in a case, without them), materials, the ground,
// gravity, explicit contacts and settings. Reading checks the schema first (types, ranges, unknown and
// missing fields), then what a schema cannot say (names, references, unit quaternions and normals,
// symmetric positive definite inertia), each error naming its JSON path.

#include "formats/input_error.hpp"
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

// The error of a frame whose shapes touch in more than max_contacts_per_frame contacts (world/world.hpp), which
// is not resolved: "frame F: the bodies' shapes touch in more than 250000 contacts, ...". Every loop that steps
// a world or detects a scene's contacts throws it, so a scene of 3000 spheres at one point is refused in words,
// not by running out of memory.
// Its own type, so that a command can say which file the scene came from.
struct ContactBudgetError : InputError {
    using InputError::InputError;
};
ContactBudgetError contact_budget_error(int frame);

}  // namespace impulse::formats
