#pragma once
// The JSON Schemas committed in schemas/, compiled into the program so that `validate` needs no files
// beside the binary, and the checks behind them. The course's own schemas (lessons, worksheets) are the
// course's (course/course_schemas.hpp).

#include "formats/json_values.hpp"

#include <string_view>

namespace impulse::formats {

std::string_view scene_schema_text();
std::string_view trace_schema_text();

// The schemas as documents are checked against them: the committed ones, with the names of the methods as the enum of
// each key that names one, from the method table (engine/methods/method_table.hpp). The committed schemas list no
// method, so adding one touches no schema, and a name the table does not hold is refused as any other word outside
// an enum is: `settings.velocity_method: must be one of "worst_first", ...; got "x"`.
json scene_schema();
json trace_schema();

// Throw InputError at the first violation; paths are prefixed with `path`.
void validate_scene_document(const json& document);
void validate_trace_document(const json& document);
void validate_settings_object(const json& settings, std::string_view path);

}  // namespace impulse::formats
