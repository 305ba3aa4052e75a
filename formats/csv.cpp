#include "formats/csv.hpp"

#include "formats/input_error.hpp"
#include "formats/input_limits.hpp"
#include "formats/json_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace impulse::formats {

namespace {

// Whether the whole text is one number as a spreadsheet reads it (a sign, digits, a point, an exponent).
bool is_number(std::string_view text) {
    if (text.starts_with('+')) text.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
}

// A spreadsheet takes a cell starting with these as a formula (or, for a tab or CR, may strip them and then do).
bool starts_like_formula(std::string_view text) {
    return !text.empty() && std::string_view("=+-@\t\r").find(text.front()) != std::string_view::npos &&
           !is_number(text);
}

}  // namespace

std::string csv_field(std::string_view text) {
    const bool guarded = starts_like_formula(text);
    if (!guarded && text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string quoted = guarded ? "\"'" : "\"";
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

void for_each_csv_row(std::string_view text, const std::function<void(const CsvRow&)>& visit) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    formats::require_utf8(text);  // its cells end up in JSON reports, which hold only UTF-8
    std::size_t line = 1, at = 0;
    CsvRow row{line, {}};
    while (at < text.size()) {
        row.line = line;
        row.fields.clear();
        std::string field;
        bool row_done = false;
        while (!row_done) {
            if (row.fields.size() == max_csv_fields)
                throw formats::InputError("line " + std::to_string(row.line),
                                          "more than " + std::to_string(max_csv_fields) +
                                              " fields in one row: not a worksheet (is the separator a comma?)");
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
        if (!empty) visit(row);
    }
}

std::vector<CsvRow> parse_csv(std::string_view text) {
    std::vector<CsvRow> rows;
    for_each_csv_row(text, [&rows](const CsvRow& row) { rows.push_back(row); });
    return rows;
}

}  // namespace impulse::formats
