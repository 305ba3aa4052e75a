#pragma once
// CSV as spreadsheets write it (RFC 4180): fields separated by commas, quoted when they hold a comma, a quote
// or a line break, a quote inside doubled. Read back with the line each row started on, for errors.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::formats {

// The field as written into a row: quoted only when it must be.
std::string csv_field(std::string_view text);
// A number as a cell: up to 9 significant digits (printf's %.9g), NaN as "NaN".
std::string csv_number(double value);
// The fields joined into one line, ending in '\n'.
std::string csv_row(const std::vector<std::string>& fields);

struct CsvRow {
    std::size_t line;  // where the row starts, counting from 1
    std::vector<std::string> fields;
};

// Every non-empty row. Accepts "\r\n" line ends and a leading UTF-8 byte-order mark (as spreadsheets save);
// throws formats::InputError("line N", ...) for a quote left open or text after a closing quote.
std::vector<CsvRow> parse_csv(std::string_view text);

}  // namespace impulse::formats
