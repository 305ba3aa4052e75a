#pragma once
// One value of a worksheet: where it is in the trace, which step computes it, and the words that describe it.
// Shared by the worksheet (its inputs and cells) and the trace items it is made of.

#include "formats/json_values.hpp"

#include <string>

namespace impulse::course {

struct WorksheetEntry {
    std::string path;      // into the trace document: "frames[0].phases[1].iterations[0].impulse_world"
    std::string step;      // the step that computes it; "given" for what the item starts from and settings
    std::string quantity;  // its name inside the item: "relative_position[0]", "updates[1].after"
    std::string unit;
    std::string formula;
    std::string equation;
    std::string meaning;
    formats::json value;  // the reference's value; a cell's is written blank
};

}  // namespace impulse::course
