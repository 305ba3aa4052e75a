#include "coursework/diff_report.hpp"

#include "explain/csv.hpp"
#include "coursework/worksheet.hpp"
#include "explain/text_table.hpp"
#include "io/input_error.hpp"
#include "io/json_text.hpp"

#include <cstdio>

namespace impulse::coursework {

namespace {

constexpr std::size_t brief_width = 40;

// A value in one short cell: scalars in full (every digit), structures shortened.
std::string brief(const io::json& value) {
    if (!value.is_structured()) return value.is_null() ? "null" : scalar_text(value);
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
    return "numbers match when |found − expected| ≤ " + io::number_text(t.atol) + " + " + io::number_text(t.rtol) +
           "·|expected|";
}

// Columns padded to their widest cell (in terminal columns), the last one left ragged.
std::string aligned(const std::vector<std::vector<std::string>>& rows, std::string_view indent) {
    std::vector<std::size_t> widths;
    for (const auto& row : rows)
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (widths.size() <= i) widths.push_back(0);
            widths[i] = std::max(widths[i], explain::display_width(row[i]));
        }
    std::string text;
    for (const auto& row : rows) {
        std::string line(indent);
        for (std::size_t i = 0; i < row.size(); ++i) {
            line += row[i];
            if (i + 1 < row.size()) line += std::string(widths[i] - explain::display_width(row[i]) + 2, ' ');
        }
        while (!line.empty() && line.back() == ' ') line.pop_back();
        text += line + '\n';
    }
    return text;
}

std::string counts(const DiffReport& r) {
    return std::to_string(r.matched) + " matched, " + std::to_string(r.mismatched) + " mismatched, " +
           std::to_string(r.blank) + " blank";
}

io::json tolerance_json(const Tolerance& t) {
    return {{"rtol", t.rtol}, {"atol", t.atol}};
}

io::json first_divergence_json(const DiffReport& r) {
    const Finding* first = r.first_divergence();
    return first ? io::json(first->path) : io::json(nullptr);
}

}  // namespace

std::string report_text(const DiffReport& report, const DiffSubject& subject) {
    std::string text = "reference " + subject.reference + "\nother     " + subject.other + " (" + report.other_kind +
                       ")\n" + tolerance_text(subject.tolerance) + "\n";
    if (!report.findings.empty()) {
        std::vector<std::vector<std::string>> rows{
            {"", "kind", "path", "expected", "found", "rel. error", "formula", "eq."}};
        for (const Finding& f : report.findings) {
            const bool no_found = f.kind == FindingKind::missing || f.kind == FindingKind::blank;
            rows.push_back(
                {f.first_divergence ? "▶" : "", std::string(finding_kind_name(f.kind)), f.path,
                 f.kind == FindingKind::extra || f.kind == FindingKind::not_in_reference ? "—" : brief(f.expected),
                 no_found ? "—" : brief(f.found), error_text(f.relative_error), f.formula, f.equation});
        }
        text += "\n" + aligned(rows, "");
    }
    text += "\n";
    if (const Finding* first = report.first_divergence())
        text += "▶ first divergence: " + first->path + (first->quantity.empty() ? "" : " (" + first->quantity + ")") +
                "; later mismatches often follow from it\n";
    text += counts(report) + (report.all_match() ? ": all match" : "") + "\n";
    return text;
}

std::string report_json(const DiffReport& report, const DiffSubject& subject) {
    io::json findings = io::json::array();
    for (const Finding& f : report.findings)
        findings.push_back({{"kind", finding_kind_name(f.kind)},
                            {"path", f.path},
                            {"expected", f.expected},
                            {"found", f.found},
                            {"relative_error", f.relative_error ? io::json(*f.relative_error) : io::json(nullptr)},
                            {"quantity", f.quantity},
                            {"formula", f.formula},
                            {"equation", f.equation},
                            {"first_divergence", f.first_divergence}});
    const io::json document = {{"reference", subject.reference},
                               {"other", subject.other},
                               {"other_kind", report.other_kind},
                               {"tolerance", tolerance_json(subject.tolerance)},
                               {"matched", report.matched},
                               {"mismatched", report.mismatched},
                               {"blank", report.blank},
                               {"all_match", report.all_match()},
                               {"first_divergence", first_divergence_json(report)},
                               {"findings", findings}};
    return io::format_json(document);
}

std::string report_csv(const DiffReport& report) {
    std::string text = "kind,path,expected,found,relative_error,quantity,formula,equation,first_divergence\n";
    const auto cell = [](const io::json& v) { return v.is_structured() ? v.dump() : scalar_text(v); };
    for (const Finding& f : report.findings)
        text += explain::csv_row({std::string(finding_kind_name(f.kind)), f.path, cell(f.expected), cell(f.found),
                                  f.relative_error ? io::number_text(*f.relative_error) : "", f.quantity, f.formula,
                                  f.equation, f.first_divergence ? "true" : "false"});
    return text;
}

std::string summary_text(const std::vector<ClassRow>& rows, const std::string& reference, const Tolerance& tolerance) {
    std::string text = "reference " + reference + "\n" + tolerance_text(tolerance) + "\n\n";
    std::vector<std::vector<std::string>> table{{"file", "matched", "mismatched", "blank", "first divergence"}};
    std::size_t perfect = 0, imperfect = 0, unreadable = 0;
    for (const ClassRow& row : rows) {
        if (!row.report) {
            ++unreadable;
            table.push_back({row.file, "", "", "", "unreadable: " + row.error});
            continue;
        }
        const DiffReport& r = *row.report;
        ++(r.all_match() ? perfect : imperfect);
        const Finding* first = r.first_divergence();
        table.push_back({row.file, std::to_string(r.matched), std::to_string(r.mismatched), std::to_string(r.blank),
                         first ? first->path : ""});
    }
    text += aligned(table, "") + "\n";
    text += std::to_string(rows.size()) + (rows.size() == 1 ? " file: " : " files: ") + std::to_string(perfect) +
            " all match, " + std::to_string(imperfect) + " with mismatches or blanks, " + std::to_string(unreadable) +
            " unreadable\n";
    return text;
}

std::string summary_json(const std::vector<ClassRow>& rows, const std::string& reference, const Tolerance& tolerance) {
    io::json files = io::json::array();
    for (const ClassRow& row : rows) {
        if (!row.report) {
            files.push_back({{"file", row.file},
                             {"matched", nullptr},
                             {"mismatched", nullptr},
                             {"blank", nullptr},
                             {"first_divergence", nullptr},
                             {"error", row.error}});
            continue;
        }
        const DiffReport& r = *row.report;
        files.push_back({{"file", row.file},
                         {"matched", r.matched},
                         {"mismatched", r.mismatched},
                         {"blank", r.blank},
                         {"first_divergence", first_divergence_json(r)},
                         {"error", nullptr}});
    }
    return io::format_json({{"reference", reference}, {"tolerance", tolerance_json(tolerance)}, {"files", files}});
}

std::string summary_csv(const std::vector<ClassRow>& rows) {
    std::string text = "file,matched,mismatched,blank,first_divergence,error\n";
    for (const ClassRow& row : rows) {
        if (!row.report) {
            text += explain::csv_row({row.file, "", "", "", "", row.error});
            continue;
        }
        const DiffReport& r = *row.report;
        const Finding* first = r.first_divergence();
        text += explain::csv_row({row.file, std::to_string(r.matched), std::to_string(r.mismatched),
                                  std::to_string(r.blank), first ? first->path : "", ""});
    }
    return text;
}

}  // namespace impulse::coursework
