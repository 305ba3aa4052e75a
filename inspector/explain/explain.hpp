#pragma once
// `resolve --explain`: the whole run told step by step in the terminal — each contact's preparation, then
// each iteration of each phase in the order they ran, every value in an annotated table.

#include "record/trace.hpp"

#include <ostream>

namespace impulse::explain {

void write_explanation(std::ostream& out, const Trace& trace);

// The short version printed without --explain: per phase what ran and how it ended, and the bodies after.
void write_summary(std::ostream& out, const Trace& trace);

}  // namespace impulse::explain
