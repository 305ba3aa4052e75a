#pragma once
// The JSON Schemas committed in schemas/, compiled into the program so that `validate` needs no files
// beside the binary, and the checks behind them.

#include "io/json_values.hpp"

#include <string_view>

namespace impulse::io {

std::string_view scene_schema_text();
std::string_view trace_schema_text();
std::string_view worksheet_schema_text();  // coursework worksheets (docs/coursework.md)
std::string_view lesson_schema_text();     // a lesson file's JSON header (docs/lessons.md)

// Throw InputError at the first violation; paths are prefixed with `path`.
void validate_scene_document(const json& document);
void validate_trace_document(const json& document);
void validate_worksheet_document(const json& document);
void validate_settings_object(const json& settings, std::string_view path);

}  // namespace impulse::io
