#pragma once
// The course's JSON Schemas (schemas/worksheet.schema.json, schemas/lesson.schema.json), compiled in so that
// lessons and worksheets are checked with no files beside the binary. Scenes and traces are the formats
// layer's (formats/schemas.hpp); a worksheet refers to the scene schema for its settings.

#include "formats/json_values.hpp"
#include "formats/schemas.hpp"

#include <string_view>

namespace impulse::course {

std::string_view worksheet_schema_text();  // coursework worksheets (docs/coursework.md)
std::string_view lesson_schema_text();     // a lesson file's JSON header (docs/lessons.md)

// Throws InputError at the first violation.
void validate_worksheet_document(const formats::json& document);

}  // namespace impulse::course
