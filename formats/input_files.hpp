#pragma once
// Reading the files a user names, and the parts of flags shared by several commands.

#include "formats/input_limits.hpp"
#include "record/trace.hpp"

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace impulse::formats {

// The default --max-trace-mb: the estimate has come to at least 0.91 of the size written (tests/formats/
// test_trace_file.cpp), so a trace stopped at 200 MB is at most about 220 MB and can still be read back under the
// 256 MiB every command reads at most (max_input_bytes).
inline constexpr double default_max_trace_mb = 200.0;

// --max-trace-mb in bytes (1 MB = 10^6 bytes).
inline std::size_t trace_budget_bytes(std::optional<double> max_trace_mb) {
    return static_cast<std::size_t>(max_trace_mb.value_or(default_max_trace_mb) * 1e6);
}

// An error about a named file: its `where` is the file, then the JSON path. Thrown on by the commands and
// printed by cli.cpp as "impulse-lab: file: path: problem".
struct FileError {
    std::string file;
    std::string where;
    std::string problem;
};

// "-" as a file argument: standard input for a file read, standard output for one written (cli/outputs.hpp).
inline constexpr std::string_view standard_stream = "-";

// What a file is called in messages: "<stdin>" for "-", else the path as given.
std::string input_name(const std::string& path);

// How long a named FIFO or device may stay silent before its first byte: a FIFO nobody writes to hung
// `validate` for ever. Standard input ("-") waits as long as its writer takes (a pipeline's first command may
// run for minutes).
inline constexpr std::chrono::milliseconds default_silence_limit{30'000};

// The whole file, or all of standard input for "-"; throws FileError if it cannot be read or is larger than
// `limit`. The limit holds while reading too, so a device or a pipe that never ends (/dev/zero) is refused
// after `limit` bytes. A named FIFO or character device is opened without waiting for a writer and read as
// data arrives; nothing within `silence` is an error ("nothing arrived within 30 s").
std::string read_input_file(const std::string& path, std::size_t limit = max_input_bytes,
                            std::chrono::milliseconds silence = default_silence_limit);

// Applies "frames=A..B" or "contacts=I,J,..." to `filter`; throws formats::InputError("--record", ...).
void apply_record_spec(std::string_view spec, TraceFilter& filter);

// The one line a command prints when its recording reached --max-trace-mb at `frame`:
// "impulse-lab: note: the trace reached --max-trace-mb 200 at frame 412 and ends with frame 411; ...".
std::string trace_stopped_note(int frame, std::optional<double> max_trace_mb);

}  // namespace impulse::formats
