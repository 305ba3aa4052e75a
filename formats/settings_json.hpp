#pragma once
// Resolver settings in JSON: a preset, then any single field changed. The same object appears in case
// files (every field optional) and in trace headers (every field written, so a trace says exactly what ran).

#include "formats/json_values.hpp"
#include "settings/settings.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace impulse::formats {

// Fills scene.settings (the resolver's) and the world's frames and damping from a settings object, which may
// be null (no settings given). The preset is `preset_override` when given, else the object's "preset", else
// "book"; the object's other fields then apply on top. Assumes the object passed the settings schema; throws
// InputError (path under `path`) for what a schema cannot say.
void read_settings(Scene& scene, const json* settings, std::string_view path,
                   const std::optional<std::string>& preset_override = std::nullopt);

json settings_json(const ResolverSettings& settings, const WorldSettings& world);

// Settings values that were renamed get an error saying what replaced them, before the schema's plainer
// "must be one of": `position_method` "baumgarte" (now the step-5 setting `baumgarte` with position_method
// "none"). `settings` may be anything; only an object is looked at. Throws InputError under `path`.
void refuse_renamed_settings(const json& settings, std::string_view path);

// Applies one `name=value` override, as `--set` gives it (value in JSON syntax, or a bare word for a
// name); throws InputError naming `flag`. `preset=P` starts the resolver settings over from that preset.
void apply_setting(Scene& scene, std::string_view assignment, std::string_view flag);

}  // namespace impulse::formats
