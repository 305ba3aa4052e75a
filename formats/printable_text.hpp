#pragma once
// Text from a file, shown to a person. A student's answer, a body's name, a JSON key or a file name may hold
// control characters: a line break would split a one-line error in two, and an escape sequence (ESC [ ...)
// reaching a teacher's terminal can move the cursor, rewrite what is shown, or set the window title. Shown
// here, each such character is written as an escape a person can read (\n, \x1b, \u009b) instead.

#include <string>
#include <string_view>

namespace impulse::formats {

// What is escaped: C0 controls (U+0000-U+001F), DEL, C1 controls (U+0080-U+009F: U+009B starts a sequence as
// ESC [ does), and the bidirectional overrides and isolates (U+202A-U+202E, U+2066-U+2069) that make text read
// in another order than it is stored. Bytes that are not UTF-8 are written as \xNN.
//
// For one line (an error, a table cell): every control, line breaks and tabs included.
std::string one_line(std::string_view text);
// For a page of lines: the same, but a line break and a tab stay what they are.
std::string printable(std::string_view text);

// How many bytes at the end of `text` could still turn into a control that one_line or printable escape
// when more text follows (an incomplete UTF-8 sequence at the end of a buffer): a stream filter keeps them back.
std::size_t incomplete_tail(std::string_view text);

}  // namespace impulse::formats
