#include "formats/csv.hpp"

#include "formats/input_error.hpp"
#include "formats/json_text.hpp"

#include <cmath>
#include <cstdio>

namespace impulse::formats {

std::string csv_field(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

std::string csv_number(double value) {
    if (std::isnan(value)) return "NaN";
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

std::string csv_row(const std::vector<std::string>& fields) {
    std::string row;
    for (std::size_t i = 0; i < fields.size(); ++i) row += (i ? "," : "") + csv_field(fields[i]);
    return row + '\n';
}

std::vector<CsvRow> parse_csv(std::string_view text) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    formats::require_utf8(text);  // its cells end up in JSON reports, which hold only UTF-8
    std::vector<CsvRow> rows;
    std::size_t line = 1, at = 0;
    while (at < text.size()) {
        CsvRow row{line, {}};
        std::string field;
        bool row_done = false;
        while (!row_done) {
            if (at < text.size() && text[at] == '"') {
                // A quoted field: up to the closing quote, "" standing for one quote.
                const std::size_t opened = line;
                ++at;
                while (true) {
                    if (at == text.size())
                        throw formats::InputError("line " + std::to_string(opened), "a quoted field is not closed");
                    if (text[at] == '"') {
                        if (at + 1 < text.size() && text[at + 1] == '"') {
                            field += '"';
                            at += 2;
                            continue;
                        }
                        ++at;
                        break;
                    }
                    if (text[at] == '\n') ++line;
                    field += text[at++];
                }
                if (at < text.size() && text[at] != ',' && text[at] != '\n' && text[at] != '\r')
                    throw formats::InputError("line " + std::to_string(line), "text after a closing quote");
            } else {
                while (at < text.size() && text[at] != ',' && text[at] != '\n' && text[at] != '\r') field += text[at++];
            }
            row.fields.push_back(std::move(field));
            field.clear();
            if (at < text.size() && text[at] == ',') {
                ++at;
                continue;
            }
            if (at < text.size() && text[at] == '\r') ++at;
            if (at < text.size() && text[at] == '\n') ++at;
            ++line;
            row_done = true;
        }
        const bool empty = row.fields.size() == 1 && row.fields[0].empty();
        if (!empty) rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace impulse::formats
