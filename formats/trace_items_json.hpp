#pragma once
// One item of a trace's frame as the trace writes it (docs/trace-format.md): a prepared contact (steps 1-5,
// frames[f].contacts[k]) or an iteration of the position or velocity phase, written and read back. Every key is a
// word of the list (formats/word_table.hpp), checked when this compiles, so the file, the code, the inspector and
// the lessons use one word for one value. The frames around the items: formats/trace_json.hpp.

#include "formats/json_values.hpp"
#include "record/trace.hpp"

namespace impulse::formats {

// Written alone, an item is what a lesson or worksheet reads a value from by its path, without writing the trace.
json item_json(const ContactPreparation& contact);
json item_json(const PositionIteration& iteration);
json item_json(const VelocityIteration& iteration);

// Read back (the item passed its schema).
ContactPreparation read_preparation(const json& j);
PositionIteration read_position_iteration(const json& j);
VelocityIteration read_velocity_iteration(const json& j);

}  // namespace impulse::formats
