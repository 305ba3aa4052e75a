#pragma once
// The derivation vocabulary, one row per quantity: its name (a table row's name and the trace key), where the
// trace keeps it, the formula that makes it, the chapter's equation, its unit, one line on what it means, the
// derivation step that computes it, and the quantities it is computed from. One table: `resolve --explain`,
// the inspector's tables, the lessons' units and what a lesson's open question hides all read it. A lesson's
// question hides its quantity and everything computed from it (`consumers`), so the inputs written here are
// what predict-then-see rests on: a missing input is an answer shown too early.

#include <string>
#include <string_view>
#include <vector>

namespace impulse::explain {

struct Annotation {
    std::string_view quantity;  // the vocabulary name (a table row's name)
    std::string_view formula;
    std::string_view equation;  // "(14.2)" from the chapter, "ch. 15" for the reference engine's additions
    std::string_view unit;
    std::string_view meaning;
    // The step whose table shows it ("basis", "impulse", "updates", ...: inspect::step_tables' names), or what
    // it is given by: "contact" (collision detection or the case file), "body" (a body's state or mass),
    // "settings", "choice" (why an iteration picked its contact).
    std::string_view step = {};
    std::string_view inputs = {};  // the quantities it is computed from, separated by spaces
    // Where an item of the trace keeps it when that is not `quantity`: "rewind.time", "updates"; and the items
    // that hold it: C a prepared contact, P a position iteration, V a velocity iteration, F the frame.
    std::string_view trace_key = {};
    std::string_view items = {};
};

// Every row, in the order of the derivation.
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

// The vocabulary row a path inside an item names: "desired_delta_velocity", "impulse_world[1]",
// "rewind.time" (rewind_time), "friction_solve.cone_limit" (cone_limit), "updates[0].after[0]" (velocity_update
// in a velocity iteration), "angular_limit.applied[0]" (angular_limit_applied). Null when none does.
const Annotation* quantity_of_path(std::string_view path, ItemKind item);

}  // namespace impulse::explain
