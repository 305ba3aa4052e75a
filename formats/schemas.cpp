#include "formats/schemas.hpp"

#include "formats/input_error.hpp"
#include "formats/schema_validator.hpp"
#include "formats/settings_names.hpp"

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

// A method table's names in its order, as a schema's enum (`skip`: a name left out).
template <typename Names>
json names_enum(const Names& names, std::string_view skip = {}) {
    json list = json::array();
    for (const auto& entry : names)
        if (entry.second != skip) list.push_back(std::string(entry.second));
    return list;
}

// The validators are built on each call rather than kept in statics (no global state); parsing the schemas
// costs well under a millisecond against the file being checked.
SchemaValidator scene_validator() {
    return SchemaValidator(scene_schema());
}

SchemaValidator trace_validator() {
    return SchemaValidator(trace_schema(), {{"scene.schema.json", scene_schema()}});
}

// A path inside `object` validated on its own becomes a path under `prefix`.
std::string under(std::string_view prefix, const std::string& where) {
    if (prefix.empty()) return where;
    if (where.empty()) return std::string(prefix);
    return std::string(prefix) + (where.front() == '[' ? "" : ".") + where;
}

}  // namespace

json scene_schema() {
    json schema = parsed(scene_schema_text());
    json& settings = schema["$defs"]["settings"]["properties"];
    settings["position_method"]["enum"] = names_enum(position_method_names);
    settings["velocity_method"]["enum"] = names_enum(velocity_method_names);
    return schema;
}

json trace_schema() {
    json schema = parsed(trace_schema_text());
    json& defs = schema["$defs"];
    defs["position_phase"]["properties"]["method"]["enum"] = names_enum(position_method_names);
    defs["velocity_phase"]["properties"]["method"]["enum"] = names_enum(velocity_method_names);
    // An iteration is made by a method that iterates: every one but `none`.
    defs["position_iteration"]["properties"]["method"]["enum"] =
        names_enum(position_method_names, name_of(position_method_names, PositionMethod::none));
    return schema;
}

void validate_scene_document(const json& document) {
    scene_validator().validate(document);
}

void validate_trace_document(const json& document) {
    trace_validator().validate(document);
}

void validate_settings_object(const json& settings, std::string_view path) {
    const SchemaValidator validator(json{{"$ref", "scene.schema.json#/$defs/settings"}},
                                    {{"scene.schema.json", scene_schema()}});
    try {
        validator.validate(settings);
    } catch (const InputError& e) {
        throw InputError(under(path, e.where()), e.problem());
    }
}

}  // namespace impulse::formats
