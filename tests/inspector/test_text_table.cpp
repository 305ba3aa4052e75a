// Text tables for a terminal: widths counted in the columns a string takes (UTF-8 code points, combining marks
// none), and plain rows of cells aligned on them, as the coursework reports print them.

#include "explain/text_table.hpp"

#include <doctest/doctest.h>

namespace impulse::test {

TEST_CASE("a string's display width counts code points and no combining marks") {
    CHECK(explain::display_width("") == 0);
    CHECK(explain::display_width("impulse") == 7);
    CHECK(explain::display_width("Δv") == 2);            // Δ is two bytes, one column
    CHECK(explain::display_width("θ̇") == 1);             // θ and a combining dot above (U+0307)
    CHECK(explain::display_width("|found − x|") == 11);  // − is three bytes
}

TEST_CASE("aligned columns pad every column but the last to its widest cell plus two spaces") {
    // Column 0: widest "file" / "a.csv" / "Δ", 5 columns, so each cell is followed by 5 - width + 2 spaces;
    // column 1 is the last: ragged, its trailing spaces dropped.
    const std::string text = explain::aligned_columns({{"file", "score"}, {"a.csv", "97.0 "}, {"Δ", ""}});
    CHECK(text ==
          "file   score\n"
          "a.csv  97.0\n"
          "Δ\n");
}

TEST_CASE("aligned columns accept rows with fewer cells and an empty table") {
    // Column 1's width is 3 ("abc"), taken from the only row that has it; the short row ends after column 0.
    CHECK(explain::aligned_columns({{"x", "abc", "y"}, {"long"}}) ==
          "x     abc  y\n"
          "long\n");
    CHECK(explain::aligned_columns({}).empty());
}

}  // namespace impulse::test
