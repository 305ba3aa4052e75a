#pragma once
// A worksheet as a student hands it back, JSON or CSV: the cells and what was written in them. Only the
// cells are graded; inputs and descriptions are read past.

#include "course/json_path.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::course {

struct FilledCell {
    std::string path;               // into the trace document
    std::vector<PathToken> tokens;  // the same, parsed
    formats::json value;            // as filled: null (or null components) = blank
    std::string where;              // where it is in the file, for errors: "steps[2].cells[0]" or "line 14"
    std::string step;               // the sheet's own words for it, where it has them (empty otherwise)
    std::string quantity;
    std::string unit;
};

struct FilledWorksheet {
    std::optional<formats::json> settings;  // the settings the sheet was made with (JSON sheets only)
    std::optional<formats::json> scene;     // the scene (JSON sheets only)
    std::vector<FilledCell> cells;
};

// Whether a parsed document is a worksheet (its "format" says so).
bool is_worksheet(const formats::json& document);

// The most cells a worksheet may hold: one per 128 bytes of the input limit (a row as `worksheet` writes it is
// longer: the 1000-box grid's first frame, 448,000 numbers, averages 173 bytes a row), so that a file of short
// rows repeated cannot make diff hold more than that many graded numbers.
inline constexpr std::size_t max_worksheet_cells = 256u * 1024 * 1024 / 128;

// Checks the worksheet schema and every cell's path; throws formats::InputError with the JSON path of the problem.
FilledWorksheet read_worksheet_json(const formats::json& document);

// An answer key: a filled worksheet given as the reference. Its cells are the places and their values the
// expected ones, as a trace document holding just those values (arrays padded with null before an index). Throws
// formats::InputError(where, ...) for a cell left blank or given twice: a key must answer each cell once.
formats::json answer_key_document(const FilledWorksheet& key);

// A worksheet CSV: a header naming at least the columns kind, path and value (the others are read past), then
// rows of kind "input" (skipped) or "cell". A cell's value is a number, true or false (in any case), empty or
// missing for blank, or any other text (graded as a wrong answer, not rejected). Throws formats::InputError("line N",
// ...).
FilledWorksheet read_worksheet_csv(std::string_view text);

}  // namespace impulse::course
