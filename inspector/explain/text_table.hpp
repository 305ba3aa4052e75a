#pragma once
// Tables as aligned text for a terminal: the step tables (columns quantity | value | formula | eq. | meaning,
// multi-line values (matrices) kept in their column), and plain rows of cells (the coursework reports).

#include "explain/derivation_table.hpp"

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::explain {

// Columns a string takes on a terminal: UTF-8 code points, combining marks (the dot of θ̇) taking none.
std::size_t display_width(std::string_view text);

void write_table(std::ostream& out, const StepTable& table, std::string_view indent = "  ");

// The same table fitted to `width` terminal columns: cells wrapped at spaces (a word longer than its column stays
// whole, never split), and when even that leaves no room, each row as its quantity and value on one line and its
// formula, equation and meaning indented below.
void write_table(std::ostream& out, const StepTable& table, std::string_view indent, std::size_t width);

// The lines of `text` at most `width` terminal columns wide, broken at spaces (its own line breaks kept); a word
// longer than a line is kept whole on its own line.
std::vector<std::string> wrap_words(std::string_view text, std::size_t width);

// One line per row: every column but the last padded to its widest cell (in terminal columns) plus two spaces,
// the last left ragged, trailing spaces dropped. Rows may have fewer cells than others.
std::string aligned_columns(const std::vector<std::vector<std::string>>& rows);

}  // namespace impulse::explain
