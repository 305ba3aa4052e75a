#pragma once
// Trace files (docs/trace-format.md, schemas/trace.schema.json): a header (format, version, conventions,
// settings, what was recorded, the scene), then frames. Inside a frame every key is a name of the
// derivation vocabulary of docs/design.md, so the file, the code, the inspector and the lessons use one word
// for one value.

#include "formats/json_values.hpp"
#include "record/trace.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace impulse::formats {

inline constexpr std::string_view trace_format_name = "impulse-lab-trace";

json trace_json(const Trace& trace);

// The trace's text as format_json(trace_json(trace)) writes it, in parts, so that a long run's frames can be
// written as they are recorded and dropped from memory: the head (every key before the frames, `trace.frames`
// is not read), each frame's text, and the end. The whole is
//   head + "[\n    " + frame + ",\n    " + frame ... + "\n  ]\n}\n", or head + "[]\n}\n" without frames,
// byte for byte what format_json writes (a test holds it).
std::string trace_head_text(const Trace& trace);
json trace_header_json(const Trace& trace);  // every key of trace_json but "frames"
std::string trace_frame_text(const FrameRecord& frame, const ResolverSettings& settings);
inline constexpr std::string_view trace_frames_open = "[\n    ", trace_frames_between = ",\n    ",
                                  trace_frames_close = "\n  ]\n}\n", trace_no_frames = "[]\n}\n";

// Checks the schema, then reads (a format-1 document upgraded first: the trace's `version` says so); throws
// InputError with the JSON path of the first problem.
Trace read_trace(const json& document);
Trace read_trace_text(std::string_view text);

}  // namespace impulse::formats
