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

// One item of a frame as the trace writes it (frames[f].contacts[k], or an iteration of a phase): for reading
// a value by its path without writing the whole trace.
json item_json(const ContactPreparation& contact);
json item_json(const PositionIteration& iteration);
json item_json(const VelocityIteration& iteration);

// Checks the schema, then reads (a format-1 document upgraded first: the trace's `version` says so); throws
// InputError with the JSON path of the first problem.
Trace read_trace(const json& document);
Trace read_trace_text(std::string_view text);

}  // namespace impulse::formats
