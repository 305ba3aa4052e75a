#include "formats/schemas.hpp"

#include "formats/input_error.hpp"
#include "formats/schema_validator.hpp"

namespace impulse::formats {

namespace embedded {
extern const std::string_view scene_schema;  // schemas/scene.schema.json, compiled in by CMake
extern const std::string_view trace_schema;  // schemas/trace.schema.json
}  // namespace embedded

std::string_view scene_schema_text() {
    return embedded::scene_schema;
}
std::string_view trace_schema_text() {
    return embedded::trace_schema;
}

namespace {

json parsed(std::string_view text) {
    return json::parse(text.begin(), text.end());
}

// The validators are built on each call rather than kept in statics (no global state); parsing the schemas
// costs well under a millisecond against the file being checked.
SchemaValidator scene_validator() {
    return SchemaValidator(parsed(scene_schema_text()));
}

SchemaValidator trace_validator() {
    return SchemaValidator(parsed(trace_schema_text()), {{"scene.schema.json", parsed(scene_schema_text())}});
}

// A path inside `object` validated on its own becomes a path under `prefix`.
std::string under(std::string_view prefix, const std::string& where) {
    if (prefix.empty()) return where;
    if (where.empty()) return std::string(prefix);
    return std::string(prefix) + (where.front() == '[' ? "" : ".") + where;
}

}  // namespace

void validate_scene_document(const json& document) {
    scene_validator().validate(document);
}

void validate_trace_document(const json& document) {
    trace_validator().validate(document);
}

void validate_settings_object(const json& settings, std::string_view path) {
    const SchemaValidator validator(json{{"$ref", "scene.schema.json#/$defs/settings"}},
                                    {{"scene.schema.json", parsed(scene_schema_text())}});
    try {
        validator.validate(settings);
    } catch (const InputError& e) {
        throw InputError(under(path, e.where()), e.problem());
    }
}

}  // namespace impulse::formats
