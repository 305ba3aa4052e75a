#include "model/derivation_view.hpp"

#include "formats/csv.hpp"

namespace impulse::model {

DerivationView derivation_view(const Trace& trace, const Cursor& cursor) {
    const std::vector<explain::StepTable> tables = step_tables(trace, cursor);
    DerivationView view;
    view.where = describe(trace, cursor);
    view.step_index = cursor.step;
    view.step_count = static_cast<int>(tables.size());
    for (int i = 0; i <= cursor.step && i < view.step_count; ++i) {
        const explain::StepTable& t = tables[static_cast<std::size_t>(i)];
        if (i == cursor.step) view.step = t.step, view.step_title = t.title;
        for (const explain::Row& r : t.rows) view.rows.push_back({t.step, r, i == cursor.step});
    }
    return view;
}

std::string derivation_csv(const DerivationView& view) {
    std::string csv = "step,quantity,value,exact,other_frame,formula,equation,meaning,changed\n";
    for (const ViewRow& r : view.rows) {
        // A matrix is formatted one row per line; in CSV its rows are joined by "; ".
        std::string value = r.row.value;
        for (std::size_t at = value.find('\n'); at != std::string::npos; at = value.find('\n', at))
            value.replace(at, 1, "; ");
        csv += formats::csv_row({r.step, r.row.quantity, value, r.row.exact, r.row.other_frame, r.row.formula,
                                 r.row.equation, r.row.meaning, r.changed ? "yes" : "no"});
    }
    return csv;
}

}  // namespace impulse::model
