#include "course/course_schemas.hpp"

#include "formats/schema_validator.hpp"
#include "formats/schemas.hpp"

namespace impulse::course::embedded {
extern const std::string_view worksheet_schema;  // schemas/worksheet.schema.json, compiled in by CMake
extern const std::string_view lesson_schema;     // schemas/lesson.schema.json
}  // namespace impulse::course::embedded

namespace impulse::course {

std::string_view worksheet_schema_text() {
    return course::embedded::worksheet_schema;
}
std::string_view lesson_schema_text() {
    return course::embedded::lesson_schema;
}

void validate_worksheet_document(const formats::json& document) {
    const auto parsed = [](std::string_view text) { return formats::json::parse(text.begin(), text.end()); };
    formats::SchemaValidator(parsed(worksheet_schema_text()), {{"scene.schema.json", formats::scene_schema()}})
        .validate(document);
}

}  // namespace impulse::course
