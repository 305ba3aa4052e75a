#pragma once
// How much one input may hold, stated once: every reader and every test of the limits uses these numbers, and
// the README and docs/fuzzing.md state them in words. A file within these limits is read in memory bounded by
// them, and in time that grows linearly with its size (docs/bench.md, "Reading").

#include <cstddef>

namespace impulse::formats {

// The most a command reads from one file. JSON documents (traces, scenes, worksheets) may be as large as the
// largest trace --max-trace-mb lets us write; text a person writes (lessons, inspect scripts, the progress file)
// is far smaller, so a wrong file named there is refused early.
inline constexpr std::size_t max_input_bytes = 256u << 20;     // 256 MiB: larger than any trace we write
inline constexpr std::size_t max_text_input_bytes = 4u << 20;  // 4 MiB: lessons, scripts, progress

// A JSON document's values as read take memory of their own: a number two characters long ("1,") is a
// 16-byte value, an empty object 3 characters and about 56 bytes. The reader estimates what it has built as it
// goes (formats/json_reader.cpp says how) and stops past this: 6 times the input limit. Traces we write take
// about 2.3 times their size (a 220 MB trace, the largest --max-trace-mb writes, about 500 MiB); a document
// written to take the most per character is refused before it costs more than this.
inline constexpr std::size_t max_json_memory_bytes = 6 * max_input_bytes;

// JSON nesting: deeper than any of our formats, shallow enough that nothing recurses far.
inline constexpr int max_json_depth = 64;

// A CSV row's fields: a worksheet has 9 columns, a spreadsheet may add some of its own. More than this is not a
// worksheet (and a row of 200 million commas would otherwise be 200 million strings).
inline constexpr std::size_t max_csv_fields = 1000;

}  // namespace impulse::formats
