#include "model/derivation_view.hpp"

namespace impulse::inspect {

namespace {

std::string csv_field(std::string text) {
    // A matrix is formatted one row per line; a CSV row stays on one line.
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at)) text.replace(at, 1, "; ");
    if (text.find_first_of(",\"\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

}  // namespace

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
    std::string csv = "step,quantity,value,other_frame,formula,equation,meaning,changed\n";
    for (const ViewRow& r : view.rows) {
        for (const std::string* field : {&r.step, &r.row.quantity, &r.row.value, &r.row.other_frame, &r.row.formula,
                                         &r.row.equation, &r.row.meaning})
            csv += csv_field(*field) + ",";
        csv += r.changed ? "yes\n" : "no\n";
    }
    return csv;
}

}  // namespace impulse::inspect
