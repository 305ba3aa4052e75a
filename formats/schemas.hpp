#pragma once
// The JSON Schemas committed in schemas/, compiled into the program so that `validate` needs no files
// beside the binary, and the checks behind them. The course's own schemas (lessons, worksheets) are the
// course's (course/course_schemas.hpp).

#include "formats/json_values.hpp"

#include <string_view>

namespace impulse::formats {

std::string_view scene_schema_text();
std::string_view trace_schema_text();

// Throw InputError at the first violation; paths are prefixed with `path`.
void validate_scene_document(const json& document);
void validate_trace_document(const json& document);
void validate_settings_object(const json& settings, std::string_view path);

}  // namespace impulse::formats
