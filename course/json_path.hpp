#pragma once
// JSON paths as the validator's errors print them (`frames[0].phases[1].iterations[0].impulse_world[1]`),
// read back: a worksheet names each of its cells by such a path into the trace document, and `diff` reports
// every mismatch by one.

#include "formats/json_values.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace impulse::course {

// One step of a path: an object key or an array index.
using PathToken = std::variant<std::string, std::size_t>;

// Whether step i of a path is the key `key`; the index at step i when that step is an index. A step past the
// path's end is neither.
bool key_at(const std::vector<PathToken>& path, std::size_t i, std::string_view key);
std::optional<std::size_t> index_at(const std::vector<PathToken>& path, std::size_t i);

// Throws formats::InputError(where, ...) when `path` is not keys and [indices] in the form json_path_child and
// json_path_index write.
std::vector<PathToken> parse_json_path(std::string_view path, std::string_view where);

// The value at `tokens` in `document`, or null when the document has no such place.
const formats::json* value_at(const formats::json& document, const std::vector<PathToken>& tokens);

// Where a path comes in the document's own order: for each token, the position of its key in the object
// (the order the file was written in) or its index. Paths compare lexicographically in trace order; a token
// the document lacks sorts after everything that exists at that level.
std::vector<std::size_t> document_position(const formats::json& document, const std::vector<PathToken>& tokens);

}  // namespace impulse::course
