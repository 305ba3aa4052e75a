#pragma once
// Reading the traces written before the word list renamed their keys (docs/trace-format.md).

#include "formats/json_values.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace impulse::formats {

// Format 1 (the keys before the word list renamed them: docs/trace-format.md) read as the current format:
// moves each renamed key of every item to its word's path and sets the version. Returns the version the
// document was written in when it was upgraded, nothing for a current document (or one that is not a trace).
std::optional<int> upgrade_trace_document(json& document);

// The line a command prints when it read a format-1 file.
std::string format1_note(std::string_view file);

}  // namespace impulse::formats
