#pragma once
// Step tables as aligned text for a terminal: columns quantity | value | formula | eq. | meaning, with
// multi-line values (matrices) kept in their column.

#include "explain/derivation_table.hpp"

#include <ostream>
#include <string_view>

namespace impulse::explain {

// Columns a string takes on a terminal: UTF-8 code points, combining marks (the dot of θ̇) taking none.
std::size_t display_width(std::string_view text);

void write_table(std::ostream& out, const StepTable& table, std::string_view indent = "  ");

}  // namespace impulse::explain
