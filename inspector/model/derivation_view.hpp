#pragma once
// The derivation table the inspector shows at the cursor: every row of the cursor's item up to and
// including the current step, the current step's rows marked as the values it changed. The same rows go
// to the window, the CSV export and the tests.

#include "model/navigator.hpp"

#include <string>
#include <vector>

namespace impulse::model {

struct ViewRow {
    std::string step;  // the vocabulary name of the step that computed this row
    explain::Row row;
    bool changed;  // computed by the current step
};

struct DerivationView {
    std::string where;       // describe(trace, cursor)
    std::string step;        // the current step's name
    std::string step_title;  // its title
    int step_index = 0;      // which of `step_count` steps this is (from 0)
    int step_count = 0;
    std::vector<ViewRow> rows;
};

DerivationView derivation_view(const Trace& trace, const Cursor& cursor);

// step,quantity,value,exact,other_frame,formula,equation,meaning,changed — RFC 4180 quoting, one row per
// line (a matrix's rows joined by "; "); `value` as shown, `exact` with every digit.
std::string derivation_csv(const DerivationView& view);

}  // namespace impulse::model
