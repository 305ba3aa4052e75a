#pragma once
// The annotated tables of a trace: for each derivation step, its values beside their formula, equation,
// unit and meaning. Plain functions of the recorded structs, so the terminal (`resolve --explain`), the
// inspector's window and the tests all see the same rows.

#include "record/trace.hpp"

#include <string>
#include <vector>

namespace impulse::explain {

struct Row {
    std::string quantity;  // the vocabulary name, with [0] / [1] for a per-body value
    std::string value;     // formatted with its unit; a matrix spans several lines
    std::string formula;
    std::string equation;
    std::string meaning;
    // A vector in the other frame where both mean something: "contact (…)" beside a world vector,
    // "world (…)" beside one in contact coordinates. Empty otherwise.
    std::string other_frame = {};
};

struct StepTable {
    std::string step;   // the step's vocabulary name ("basis", "velocity_change", ...)
    std::string title;  // "Step 1 · basis — contact coordinates from the normal"
    std::vector<Row> rows;
};

// Steps 1-5 of a contact, as prepared at the start of the frame.
std::vector<StepTable> preparation_tables(const ContactPreparation& contact);

// Step 8 for one position iteration (empty when its derivation was filtered out of the recording), then a
// table of the updates it made to other contacts' penetrations. With the chosen contact's basis, world
// vectors are also given in contact coordinates.
std::vector<StepTable> position_iteration_tables(const PositionIteration& iteration,
                                                 const Mat3* contact_to_world = nullptr);

// Where a sweeping solver was: "sub-step 1 · solve sweep 2" (the sub-step only where the method sub-steps:
// `settings` soft step), and what that stage does.
std::string sweep_text(const SweepPlace& sweep, const ResolverSettings& settings);
std::string sweep_meaning(SolverStage stage);

// Steps 4-7 for one velocity iteration (with the accumulated impulse and its clamp for the accumulating
// solvers), then its updates.
std::vector<StepTable> velocity_iteration_tables(const VelocityIteration& iteration,
                                                 const Mat3* contact_to_world = nullptr);

}  // namespace impulse::explain
