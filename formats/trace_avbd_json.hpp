#pragma once
// AVBD's iterations in a trace (record/avbd_records.hpp): a body visit's and a dual update's keys inside a velocity
// iteration, written and read back. Every key is a word of the list (formats/word_table.hpp), checked when this
// compiles.

#include "formats/json_values.hpp"
#include "record/iteration_records.hpp"

namespace impulse::formats {

// Whether `it` is one of AVBD's iterations, which record no desired delta v or epsilon.
bool is_avbd_iteration(const VelocityIteration& it);

// Adds the body visit's or dual update's keys of `it` to `out`.
void write_avbd_iteration(const VelocityIteration& it, json& out);

// Reads them back into `it` (the iteration passed its schema).
void read_avbd_iteration(const json& j, VelocityIteration& it);

}  // namespace impulse::formats
