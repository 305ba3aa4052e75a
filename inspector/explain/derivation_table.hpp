#pragma once
// The annotated tables of a trace: for each derivation step, its values beside their formula, equation,
// unit and meaning. Plain functions of the recorded structs, so the terminal (`resolve --explain`), the
// inspector's window, the lessons and the tests all see the same rows. Steps are named, not numbered: the
// chapter numbers its steps differently from one method to another, and a lesson numbers its own.

#include "record/trace.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::explain {

struct Row {
    std::string quantity;  // the vocabulary name, with [0] / [1] for a per-body value; "contact 3" for an update
    std::string value;     // formatted with its unit; a matrix spans several lines; rounding noise shown as 0
    std::string formula;
    std::string equation;
    std::string meaning;
    // A vector in the other frame where both mean something: "contact (…)" beside a world vector,
    // "world (…)" beside one in contact coordinates. Empty otherwise.
    std::string other_frame = {};
    std::string key = {};    // the vocabulary name (explain/annotations.hpp): what a lesson's question hides
    std::string exact = {};  // the value with every digit (17 significant), for a tooltip and exports
};

struct StepTable {
    std::string step;   // the step's vocabulary name ("basis", "velocity_change", ...)
    std::string title;  // "basis — contact coordinates from the normal"
    std::vector<Row> rows;
};

// A prepared contact's tables: basis, relative_position, velocity_per_unit_impulse, contact_velocity,
// desired_delta_velocity.
std::vector<StepTable> preparation_tables(const ContactPreparation& contact);

// A position iteration's tables (none when its derivation was filtered out of the recording): the rewind
// (velocity-based), penetration_inertia, move_split, position_change, then the updates it made to other
// contacts' penetrations. With the chosen contact's basis, world vectors are also given in contact coordinates.
std::vector<StepTable> position_iteration_tables(const PositionIteration& iteration,
                                                 const Mat3* contact_to_world = nullptr);

// Where a sweeping solver was: "sub-step 1 · solve sweep 2" (the sub-step only where the method sub-steps:
// `settings` soft step), and what that stage does.
std::string sweep_text(const SweepPlace& sweep, const ResolverSettings& settings);
std::string sweep_meaning(SolverStage stage);

// A velocity iteration's tables: contact_velocity, desired_delta_velocity (and the position bias, the
// accumulated impulse for the accumulating solvers), impulse, velocity_change, then its updates.
std::vector<StepTable> velocity_iteration_tables(const VelocityIteration& iteration,
                                                 const Mat3* contact_to_world = nullptr);

// The steps of an item's tables, in order, read from the record's shape without formatting a value: what the
// navigator counts, names and moves by. Each list is the `step` of the tables the functions above make.
std::vector<std::string_view> preparation_steps(const ContactPreparation& contact);
std::vector<std::string_view> position_iteration_steps(const PositionIteration& iteration);
std::vector<std::string_view> velocity_iteration_steps(const VelocityIteration& iteration);

}  // namespace impulse::explain
