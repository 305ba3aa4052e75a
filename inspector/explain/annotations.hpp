#pragma once
// The derivation vocabulary as the inspector reads it: the word list of formats/words.hpp, one row per
// name (its key in the trace, a table row's name, a lesson's value), with the formula that makes it, the
// chapter's equation, its unit, one line on what it means, the derivation step that computes it, and the
// quantities it is computed from. `resolve --explain`, the inspector's tables, the lessons' units and what a
// lesson's open question hides all read it. A lesson's
// question hides its quantity and everything computed from it (`consumers`), so the inputs written here are
// what predict-then-see rests on: a missing input is an answer shown too early.

#include "formats/words.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace impulse::explain {

// A row of the word list (formats/words.hpp): the inspector reads the one table every layer reads.
using Annotation = formats::words::Word;

// Every name once (the first word of a name, where items of different kinds hold different words of it), in
// the order of the derivation.
const std::vector<Annotation>& vocabulary();

// The annotation of a vocabulary name; a name not in the table is a programming error (asserted).
const Annotation& annotation(std::string_view quantity);

// The annotation of a name that may not be in the vocabulary (a key read from a file), or null.
const Annotation* find_annotation(std::string_view quantity);

// The names in a row's `inputs`.
std::vector<std::string_view> inputs_of(const Annotation& a);

// The quantities computed from `quantity`, directly or through others (not `quantity` itself).
std::vector<std::string_view> consumers(std::string_view quantity);

// The kind of trace item a path is read in: a prepared contact, a position or a velocity iteration.
enum class ItemKind { contact, position_iteration, velocity_iteration };

// The vocabulary row a path inside an item names: "desired_delta_velocity", "impulse_world[1]", "rewind.time",
// "friction_solve.cone_limit", "angular_limit.applied[0]": the path without its indices; "updates[0].after[0]"
// names velocity_update in a velocity iteration, penetration_update in a position iteration. Null when none does.
const Annotation* quantity_of_path(std::string_view path, ItemKind item);

}  // namespace impulse::explain
