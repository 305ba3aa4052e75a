#pragma once
// AVBD's iterations as annotated tables (record/avbd_records.hpp): a body visit shows the contacts its block
// gathered (their constraint C*, then their lambda, k and force F), the block H and f, and the move H^-1 f; a
// contact's dual update shows its constraint and force at the bodies' new positions and its new lambda and k.

#include "explain/derivation_table.hpp"

namespace impulse::explain {

// Whether an iteration is one of AVBD's body visits or dual updates (a dual update filtered out of the recording
// keeps only its place).
bool is_avbd_visit(const VelocityIteration& iteration);

// The choice table of an AVBD iteration: where in the sweeps, and which body (a body visit) or contact (a dual
// update).
StepTable avbd_choice_table(const VelocityIteration& iteration, const ResolverSettings& settings);

std::vector<StepTable> avbd_iteration_tables(const VelocityIteration& iteration);
std::vector<std::string_view> avbd_iteration_steps(const VelocityIteration& iteration);

}  // namespace impulse::explain
