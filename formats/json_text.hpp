#pragma once
// JSON text in and out. Reading is strict where nlohmann is lenient: a key given twice in one object is an
// error (the second would silently win), and so is nesting deeper than a fixed limit or a document larger in
// memory than a file within the input limit can need. Writing keeps short
// arrays (vectors, matrix rows) on one line so a person can read a trace.

#include "formats/input_limits.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace impulse::formats {

// Throws InputError: "invalid JSON at line 3, column 7: ..." (no path), "<path>: key given twice", or at the
// value where it happens, nesting deeper than max_json_depth or a document that would take more memory than
// `memory_limit` (formats/json_reader.cpp). Time and memory grow linearly with the text.
nlohmann::ordered_json parse_json_text(std::string_view text, std::size_t memory_limit = max_json_memory_bytes);

// Where `text` stops being UTF-8: the offset of the first byte that does not belong (none: it is all UTF-8).
// For text read outside JSON (CSV, Markdown), which nlohmann would otherwise refuse only when writing it.
std::optional<std::size_t> first_non_utf8_byte(std::string_view text);

// Throws InputError("line 3", "not UTF-8 text: byte 0x98 at column 41") unless `text` is all UTF-8.
void require_utf8(std::string_view text);

// Indented two spaces; arrays of numbers (and arrays of such arrays) on one line. Doubles keep 17
// significant digits, so a value read back is the same to the last bit.
std::string format_json(const nlohmann::ordered_json& value);
// The same for a value `indent` levels deep (two spaces each) in a larger document, appended to `out` (no line
// break after it): the pieces of a document written a part at a time (formats/trace_json.hpp).
void append_json(const nlohmann::ordered_json& value, int indent, std::string& out);

}  // namespace impulse::formats
