#pragma once
// CSV as spreadsheets write it (RFC 4180): fields separated by commas, quoted when they hold a comma, a quote
// or a line break, a quote inside doubled. Read back with the line each row started on, for errors.
//
// Text from anyone (a student's answer, a body's name) can start like a formula: a spreadsheet opening the file
// would run "=cmd|' /C calc'!A0". As OWASP's CSV-injection guidance says, a field that starts with = + - @, a tab
// or a carriage return, and is not a number, is written quoted with a ' before it, which spreadsheets show as
// text; numbers (-0.5, +3) are written as they are.

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::formats {

// The field as written into a row: quoted only when it must be, and guarded as above.
std::string csv_field(std::string_view text);
// A number as a cell: up to 9 significant digits (printf's %.9g), NaN as "NaN".
std::string csv_number(double value);
// The fields joined into one line, ending in '\n'.
std::string csv_row(const std::vector<std::string>& fields);

struct CsvRow {
    std::size_t line;  // where the row starts, counting from 1
    std::vector<std::string> fields;
};

// Calls `row` with every non-empty row in turn, so a large file is never held as rows all at once. Accepts
// "\r\n" line ends and a leading UTF-8 byte-order mark (as spreadsheets save); throws
// formats::InputError("line N", ...) for text that is not UTF-8, a quote left open, text after a closing quote
// or a row of more than max_csv_fields fields (formats/input_limits.hpp).
void for_each_csv_row(std::string_view text, const std::function<void(const CsvRow&)>& row);

// Every non-empty row, as for_each_csv_row reads them.
std::vector<CsvRow> parse_csv(std::string_view text);

}  // namespace impulse::formats
