#include "course/diff_report.hpp"

#include "formats/csv.hpp"
#include "course/worksheet.hpp"
#include "explain/text_table.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/printable_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impulse::course {

namespace {

constexpr std::size_t brief_width = 40;

// A value in one short cell: an expected number to the digits the tolerance looks at (shown_value), a found one
// as written; structures shortened.
std::string brief(const formats::json& value, const std::optional<Tolerance>& tolerance) {
    if (!value.is_structured()) {
        if (value.is_null()) return "null";
        return tolerance ? shown_value(value, *tolerance) : scalar_text(value);
    }
    std::string text;
    if (value.is_object()) {
        // Elements that carry their own number (an iteration, a contact) are named by it.
        for (const char* id : {"frame", "phase", "iteration", "contact"})
            if (value.contains(id)) text += std::string(text.empty() ? "" : ", ") + id + " " + scalar_text(value[id]);
        if (!text.empty()) return text;
    }
    text = value.dump();
    if (text.size() > brief_width) text = text.substr(0, brief_width - 1) + "…";
    return text;
}

std::string error_text(const std::optional<double>& e) {
    if (!e) return "";
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", *e);
    return text;
}

std::string tolerance_text(const Tolerance& t) {
    return "numbers match when |found − expected| ≤ " + formats::number_text(t.atol) + " + " +
           formats::number_text(t.rtol) + "·|expected|";
}

}  // namespace

std::string shown_value(const formats::json& value, const Tolerance& tolerance) {
    if (!value.is_number_float())
        return value.is_null() ? "" : value.is_structured() ? value.dump() : scalar_text(value);
    if (value.get<double>() == 0.0) return "0";  // and −0
    const double rtol = tolerance.rtol;
    const int digits = rtol > 0 ? std::clamp(static_cast<int>(std::ceil(-std::log10(rtol))) + 2, 6, 17) : 17;
    char text[48];
    std::snprintf(text, sizeof text, "%.*g", digits, value.get<double>());
    // The shortest text that reads back the same when it is shorter (0.25, not 0.250000).
    const std::string exact = formats::number_text(value.get<double>());
    return exact.size() <= std::string(text).size() ? exact : text;
}

bool empty_sheet(const DiffReport& report) {
    return std::any_of(report.findings.begin(), report.findings.end(),
                       [](const Finding& f) { return f.kind == FindingKind::empty; });
}

std::string worded(const Finding& f) {
    return f.place.empty() ? f.quantity : f.place + ": " + f.quantity;
}

std::string percent_text(double percent) {
    char text[32];
    std::snprintf(text, sizeof text, percent >= 99.95 && percent < 100.0 ? "%.2f %%" : "%.1f %%", percent);
    return text;
}

std::string findings_table(const std::vector<Finding>& findings, std::size_t limit, const Tolerance& tolerance) {
    std::vector<std::vector<std::string>> rows{
        {"", "kind", "quantity", "expected", "found", "unit", "rel. error", "formula", "eq."}};
    std::vector<std::string> places{""};
    for (std::size_t i = 0; i < findings.size() && i < limit; ++i) {
        const Finding& f = findings[i];
        const bool no_found =
            f.kind == FindingKind::missing || f.kind == FindingKind::blank || f.kind == FindingKind::empty;
        const bool no_expected =
            f.kind == FindingKind::extra || f.kind == FindingKind::not_in_reference || f.kind == FindingKind::empty;
        // A found value is what a student wrote: a line break or an escape sequence in it is shown, not obeyed
        // (a line break in a cell once split the table's rows from their places: a read past the end).
        rows.push_back({f.first_divergence ? "▶" : "", std::string(finding_kind_name(f.kind)),
                        formats::one_line(f.quantity),
                        no_expected ? "—" : formats::one_line(brief(f.expected, tolerance)),
                        no_found ? "—" : formats::one_line(brief(f.found, std::nullopt)), f.unit,
                        error_text(f.relative_error), f.formula, f.equation});
        places.push_back(formats::one_line(f.place));
    }
    // One line per row, under a line naming the place (the worksheet's step) whenever it changes.
    const std::string table = explain::aligned_columns(rows);
    std::string text;
    std::size_t row = 0, start = 0;
    for (std::size_t end = table.find('\n'); end != std::string::npos; start = end + 1, end = table.find('\n', start)) {
        if (row > 0 && row < places.size() && !places[row].empty() && places[row] != places[row - 1])
            text += places[row] + "\n";
        text += table.substr(start, end - start + 1);
        ++row;
    }
    return text;
}

namespace {}  // namespace

bool later_divergence(const DiffReport& r, const Finding& first) {
    bool after = false;
    for (const Finding& f : r.findings) {
        if (&f == &first) {
            after = true;
            continue;
        }
        if (after && (f.kind == FindingKind::value || f.kind == FindingKind::missing || f.kind == FindingKind::extra))
            return true;
    }
    return false;
}

namespace {

std::string counts(const DiffReport& r) {
    return std::to_string(r.matched) + " matched, " + std::to_string(r.mismatched) + " mismatched, " +
           std::to_string(r.blank) + " blank";
}

formats::json tolerance_json(const Tolerance& t) {
    return {{"rtol", t.rtol}, {"atol", t.atol}};
}

formats::json score_json(const DiffReport& r) {
    const Score score = score_of(r);
    return score.percent ? formats::json(*score.percent) : formats::json(nullptr);
}

formats::json first_divergence_json(const DiffReport& r) {
    const Finding* first = r.first_divergence();
    return first ? formats::json(first->path) : formats::json(nullptr);
}

}  // namespace

std::string report_text(const DiffReport& report, const DiffSubject& subject) {
    std::string text = "reference " + formats::one_line(subject.reference) + "\nother     " +
                       formats::one_line(subject.other) + " (" + report.other_kind + ")\n" +
                       tolerance_text(subject.tolerance) + "\n";
    if (!report.findings.empty())
        text += "\n" + findings_table(report.findings, report.findings.size(), subject.tolerance);
    text += "\n";
    if (const Finding* first = report.first_divergence())
        text += "▶ first divergence: " + formats::one_line(worded(*first)) + " (" + first->path + ")" +
                (later_divergence(report, *first) ? "; later mismatches often follow from it" : "") + "\n";
    const Score score = score_of(report);
    if (report.other_kind == "worksheet" && empty_sheet(report))
        text += "the worksheet gives no cells: nothing to grade\n";
    text += counts(report) + (report.all_match() ? ": all match" : "") +
            (score.percent ? "; score " + percent_text(*score.percent) : "") + "\n";
    return text;
}

std::string report_json(const DiffReport& report, const DiffSubject& subject) {
    formats::json findings = formats::json::array();
    for (const Finding& f : report.findings)
        findings.push_back(
            {{"kind", finding_kind_name(f.kind)},
             {"path", f.path},
             {"expected", f.expected},
             {"found", f.found},
             {"relative_error", f.relative_error ? formats::json(*f.relative_error) : formats::json(nullptr)},
             {"place", f.place},
             {"quantity", f.quantity},
             {"unit", f.unit},
             {"formula", f.formula},
             {"equation", f.equation},
             {"first_divergence", f.first_divergence}});
    const formats::json document = {{"reference", subject.reference},
                                    {"other", subject.other},
                                    {"other_kind", report.other_kind},
                                    {"tolerance", tolerance_json(subject.tolerance)},
                                    {"matched", report.matched},
                                    {"mismatched", report.mismatched},
                                    {"blank", report.blank},
                                    {"all_match", report.all_match()},
                                    {"score_percent", score_json(report)},
                                    {"first_divergence", first_divergence_json(report)},
                                    {"findings", findings}};
    return formats::format_json(document);
}

std::string report_csv(const DiffReport& report) {
    std::string text =
        "kind,path,expected,found,relative_error,quantity,formula,equation,first_divergence,place,unit\n";
    const auto cell = [](const formats::json& v) { return v.is_structured() ? v.dump() : scalar_text(v); };
    for (const Finding& f : report.findings)
        text += formats::csv_row({std::string(finding_kind_name(f.kind)), f.path, cell(f.expected), cell(f.found),
                                  f.relative_error ? formats::number_text(*f.relative_error) : "", f.quantity,
                                  f.formula, f.equation, f.first_divergence ? "true" : "false", f.place, f.unit});
    return text;
}

}  // namespace impulse::course
