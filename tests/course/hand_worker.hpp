#pragma once
// A hand worker for the worksheets' blank-cell test (test_blank_cells.cpp): it reads only a worksheet's document, its
// inputs (rounded for work by hand, as written) and the cells it has already filled, and applies each step's formula
// with the engine's own derivation functions, as a student applies the chapter's equations on paper, filling the
// cells step after step in whatever order the sheet's steps can be done.
//
// Only one thing is read from the reference trace: which earlier iteration last changed a contact (the bookkeeping a
// student follows through the sheet's update tables), never a value.

#include "formats/json_values.hpp"

#include <string>
#include <vector>

namespace impulse::test {

struct HandWork {
    formats::json filled;             // the sheet with every cell it could work out filled
    std::vector<std::string> undone;  // each step it could not do, and the value it waited for
};

HandWork work_by_hand(const formats::json& sheet, const formats::json& reference);

}  // namespace impulse::test
