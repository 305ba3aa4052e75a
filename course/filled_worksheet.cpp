#include "course/filled_worksheet.hpp"

#include "formats/csv.hpp"
#include "course/worksheet.hpp"
#include "formats/input_error.hpp"
#include "course/course_schemas.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

namespace impulse::course {

namespace {

std::string trimmed(std::string_view text) {
    const auto space = [](char c) { return c == ' ' || c == '\t'; };
    while (!text.empty() && space(text.front())) text.remove_prefix(1);
    while (!text.empty() && space(text.back())) text.remove_suffix(1);
    return std::string(text);
}

// A CSV value as JSON: empty is blank (null), then a number, true/false, else the text itself.
formats::json csv_value(std::string_view field) {
    const std::string text = trimmed(field);
    if (text.empty()) return nullptr;
    // Spreadsheets write booleans in capitals.
    std::string lower = text;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "true") return true;
    if (lower == "false") return false;
    std::string_view digits = text;
    if (digits.front() == '+') digits.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc() && end == digits.data() + digits.size() && std::isfinite(value)) return value;
    return text;
}

[[noreturn]] void too_many_cells(const std::string& where) {
    throw formats::InputError(where, "more than " + std::to_string(max_worksheet_cells) +
                                         " cells: more than any worksheet within the input limit holds");
}

// Sets `value` at `tokens` in `document`, making the objects and arrays on the way (an array padded with null,
// at most `padding` nulls in all: a path with an index of a billion asks for a billion of them).
void place_at(formats::json& document, const std::vector<PathToken>& tokens, const formats::json& value,
              const std::string& where, std::size_t& padding) {
    formats::json* here = &document;
    for (const PathToken& token : tokens) {
        if (const auto* key = std::get_if<std::string>(&token)) {
            if (here->is_null()) *here = formats::json::object();
            if (!here->is_object())
                throw formats::InputError(where, "the path goes into a number of another cell as if it were a list");
            here = &(*here)[*key];
        } else {
            const std::size_t index = std::get<std::size_t>(token);
            if (here->is_null()) *here = formats::json::array();
            if (!here->is_array()) throw formats::InputError(where, "the path does not fit the other cells' paths");
            if (index >= here->size() && index - here->size() >= padding)
                throw formats::InputError(where, "the index " + std::to_string(index) +
                                                     " leaves more places empty than a key of this size can");
            while (here->size() <= index) {
                here->push_back(nullptr);
                --padding;
            }
            here = &(*here)[index];
        }
    }
    if (!here->is_null()) throw formats::InputError(where, "gives a cell an earlier row gives already");
    *here = value;
}

bool has_blank(const formats::json& value) {
    if (value.is_null()) return true;
    return value.is_array() && std::any_of(value.begin(), value.end(), has_blank);
}

}  // namespace

formats::json answer_key_document(const FilledWorksheet& key) {
    formats::json document = formats::json::object();
    std::size_t padding = max_worksheet_cells;
    for (const FilledCell& cell : key.cells) {
        if (has_blank(cell.value))
            throw formats::InputError(cell.where,
                                      "is blank: an answer key given as the reference must fill every "
                                      "cell (or give the lesson, case, scene or JSON worksheet it was made "
                                      "from, which diff re-runs)");
        place_at(document, cell.tokens, cell.value, cell.where, padding);
    }
    return document;
}

bool is_worksheet(const formats::json& document) {
    return document.is_object() && document.contains("format") && document["format"] == worksheet_format_name;
}

FilledWorksheet read_worksheet_json(const formats::json& document) {
    course::validate_worksheet_document(document);
    FilledWorksheet sheet;
    if (document.contains("settings")) sheet.settings = document["settings"];
    if (document.contains("reference")) sheet.scene = document["reference"]["scene"];
    const formats::json& steps = document["steps"];
    for (std::size_t s = 0; s < steps.size(); ++s) {
        const std::string step_path = formats::json_path_index("steps", s);
        const formats::json& cells = steps[s]["cells"];
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const std::string where = formats::json_path_index(formats::json_path_child(step_path, "cells"), c);
            const std::string path = cells[c]["path"].get<std::string>();
            if (sheet.cells.size() == max_worksheet_cells) too_many_cells(where);
            sheet.cells.push_back({path, parse_json_path(path, formats::json_path_child(where, "path")),
                                   cells[c]["value"], where, cells[c].value("step", ""), cells[c].value("quantity", ""),
                                   cells[c].value("unit", "")});
        }
    }
    return sheet;
}

FilledWorksheet read_worksheet_csv(std::string_view text) {
    FilledWorksheet sheet;
    std::vector<std::string> header;
    std::size_t kind = 0, path = 0, value = 0, needed = 0;
    std::optional<std::size_t> step, quantity, unit;  // the sheet's own words, when it kept those columns
    const auto column = [&header](const char* name) {
        const auto found =
            std::find_if(header.begin(), header.end(), [name](const std::string& h) { return trimmed(h) == name; });
        if (found == header.end())
            throw formats::InputError("line 1", std::string("the header has no column \"") + name + "\" (expected " +
                                                    std::string(worksheet_csv_header) + ")");
        return static_cast<std::size_t>(found - header.begin());
    };
    formats::for_each_csv_row(text, [&](const formats::CsvRow& row) {
        if (header.empty()) {
            header = row.fields;
            kind = column("kind"), path = column("path"), value = column("value");
            const auto optional_column = [&header](const char* name) -> std::optional<std::size_t> {
                const auto found = std::find_if(header.begin(), header.end(),
                                                [name](const std::string& h) { return trimmed(h) == name; });
                if (found == header.end()) return std::nullopt;
                return static_cast<std::size_t>(found - header.begin());
            };
            step = optional_column("step"), quantity = optional_column("quantity"), unit = optional_column("unit");
            // A row may stop early when its last fields are empty (some programs write it so): a missing value is
            // blank.
            needed = std::max(kind, path) + 1;
            return;
        }
        const std::string where = "line " + std::to_string(row.line);
        if (row.fields.size() < needed)
            throw formats::InputError(where, "has " + std::to_string(row.fields.size()) + " columns, the header " +
                                                 std::to_string(header.size()));
        const std::string k = trimmed(row.fields[kind]);
        if (k == "input") return;
        if (k != "cell") throw formats::InputError(where, "kind must be \"input\" or \"cell\", got \"" + k + "\"");
        const std::string p = trimmed(row.fields[path]);
        const std::string filled = value < row.fields.size() ? row.fields[value] : "";
        const auto field = [&row](const std::optional<std::size_t>& at) {
            return at && *at < row.fields.size() ? trimmed(row.fields[*at]) : std::string();
        };
        if (sheet.cells.size() == max_worksheet_cells) too_many_cells(where);
        sheet.cells.push_back({p, parse_json_path(p, where + ": path"), csv_value(filled), where, field(step),
                               field(quantity), field(unit)});
    });
    if (header.empty()) throw formats::InputError("line 1", "no header: expected " + std::string(worksheet_csv_header));
    return sheet;
}

}  // namespace impulse::course
