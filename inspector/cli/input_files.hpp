#pragma once
// Reading the files a user names, and the parts of flags shared by several commands.

#include "record/trace.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace impulse::cli {

inline constexpr std::size_t max_input_bytes = 256u << 20;  // 256 MiB: larger than any trace we write

// An error about a named file: its `where` is the file, then the JSON path. Thrown on by the commands and
// printed by cli.cpp as "impulse-lab: file: path: problem".
struct FileError {
    std::string file;
    std::string where;
    std::string problem;
};

// The whole file; throws FileError if it cannot be read or is larger than the limit.
std::string read_input_file(const std::string& path);

// Applies "frames=A..B" or "contacts=I,J,..." to `filter`; throws io::InputError("--record", ...).
void apply_record_spec(std::string_view spec, TraceFilter& filter);

// The one line a command prints when its recording reached --max-trace-mb at `frame`:
// "impulse-lab: note: the trace reached --max-trace-mb 200 at frame 412 and ends with frame 411; ...".
std::string trace_stopped_note(int frame, std::optional<double> max_trace_mb);

}  // namespace impulse::cli
