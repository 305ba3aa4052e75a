#include "course/class_report.hpp"

#include "course/slips.hpp"
#include "course/worksheet.hpp"
#include "formats/csv.hpp"
#include "explain/text_table.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/printable_text.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace impulse::course {

namespace {

std::string count_text(std::size_t n) {
    return std::to_string(n);
}

std::string tolerance_words(const Tolerance& t) {
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.6g", t.rtol * 100);  // 1e-07, not 1.0000000000000001e-07
    return "|yours − expected| ≤ " + formats::number_text(t.atol) + " + " + formats::number_text(t.rtol) +
           "·|expected| (" + percent + " % of the expected value, or " + formats::number_text(t.atol) +
           " when it is 0)";
}

// "10.4 % off", or for an expected 0 "off by 0.002 N·s".
std::string how_far(const std::optional<double>& relative_error, const formats::json& expected,
                    const std::string& unit) {
    if (!relative_error) return "";
    char text[48];
    if (expected.is_number() && expected.get<double>() == 0.0) {
        std::snprintf(text, sizeof text, "off by %.3g", *relative_error);
        return std::string(text) + (unit.empty() ? "" : " " + unit);
    }
    const double percent = *relative_error * 100.0;
    std::snprintf(text, sizeof text, percent < 1000.0 ? "%.3g %% off" : "%.0f %% off", percent);
    return text;
}

// A wrong number that is the expected one times a telling factor: what the slip probably was (course/slips.hpp).
std::string slip_of(const formats::json& expected, const formats::json& found) {
    if (!expected.is_number() || !found.is_number()) return "";
    return course::likely_slip(expected.get<double>(), found.get<double>());
}

// Text on a feedback page as text, whatever it holds: a student's answer or a file's name may hold Markdown
// (`**`, `[link](…)`, a `|` that ends a table cell) or HTML (<script>, <img onerror=…>) that a page viewer would
// render or run. HTML's three characters become entities, Markdown's punctuation is escaped with a backslash, and
// controls and line breaks are shown as escapes (formats::one_line), so the text stays on its line of the table.
std::string md_text(const std::string& text) {
    std::string out;
    for (const char c : formats::one_line(text)) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (std::string_view("\\`*_{}[]()#+!|~").find(c) != std::string_view::npos)
            out += std::string("\\") + c;
        else
            out += c;
    }
    return out;
}

// Markdown table cells of our own words may not hold a '|' (|v_s| in a formula) or a line break.
std::string md_cell(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '|')
            out += "\\|";
        else if (c == '\n')
            out += ' ';
        else
            out += c;
    }
    return out;
}

// Our own words (a quantity, a place) in code style; anything a backtick could end is shown as text instead.
std::string code(const std::string& text) {
    if (text.empty()) return "";
    if (text.find_first_of("`\n\r") != std::string::npos) return md_text(text);
    return "`" + text + "`";
}

std::string first_words(const DiffReport& r) {
    const Finding* first = r.first_divergence();
    return first ? worded(*first) : "";
}

// The lines of the summary table for one file.
std::vector<std::string> summary_cells(const ClassRow& row) {
    if (!row.report)
        return {formats::one_line(row.file), "", "", "", "", "", "unreadable: " + formats::one_line(row.error)};
    const Score s = score_of(*row.report);
    return {formats::one_line(row.file), s.percent ? percent_text(*s.percent) : "—",
            count_text(s.cells),         count_text(s.right),
            count_text(s.wrong),         count_text(s.blank),
            first_words(*row.report)};
}

}  // namespace

std::string summary_text(const std::vector<ClassRow>& rows, const ClassSubject& subject, std::size_t per_file) {
    std::string text = "reference " + formats::one_line(subject.reference) +
                       (subject.what.empty() ? "" : " (" + formats::one_line(subject.what) + ")") +
                       "\nnumbers match when |found − expected| ≤ " + formats::number_text(subject.tolerance.atol) +
                       " + " + formats::number_text(subject.tolerance.rtol) + "·|expected|\n\n";
    std::vector<std::vector<std::string>> table{
        {"file", "score", "cells", "matched", "mismatched", "blank", "first divergence"}};
    std::size_t perfect = 0, imperfect = 0, unreadable = 0;
    for (const ClassRow& row : rows) {
        table.push_back(summary_cells(row));
        if (!row.report)
            ++unreadable;
        else
            ++(row.report->all_match() ? perfect : imperfect);
    }
    text += explain::aligned_columns(table);
    // What each file got wrong, as its worksheet names it.
    for (const ClassRow& row : rows) {
        if (!row.report || row.report->findings.empty()) continue;
        const std::vector<Finding>& findings = row.report->findings;
        text += "\n" + formats::one_line(row.file) + ": " + count_text(findings.size()) +
                (findings.size() == 1 ? " finding" : " findings") + "\n";
        text += findings_table(findings, per_file, subject.tolerance);
        if (findings.size() > per_file)
            text += "… and " + count_text(findings.size() - per_file) + " more (diff " +
                    formats::one_line(subject.reference) + " " + formats::one_line(row.file) +
                    " shows them all; --out DIR writes every file's)\n";
    }
    text += "\n" + count_text(rows.size()) + (rows.size() == 1 ? " file: " : " files: ") + count_text(perfect) +
            " all match, " + count_text(imperfect) + " with mismatches or blanks, " + count_text(unreadable) +
            " unreadable\n";
    return text;
}

std::string summary_json(const std::vector<ClassRow>& rows, const ClassSubject& subject) {
    formats::json files = formats::json::array();
    for (const ClassRow& row : rows) {
        if (!row.report) {
            files.push_back({{"file", row.file},
                             {"kind", nullptr},
                             {"cells", nullptr},
                             {"matched", nullptr},
                             {"mismatched", nullptr},
                             {"blank", nullptr},
                             {"score_percent", nullptr},
                             {"first_divergence", nullptr},
                             {"first_divergence_path", nullptr},
                             {"error", row.error}});
            continue;
        }
        const DiffReport& r = *row.report;
        const Score s = score_of(r);
        const Finding* first = r.first_divergence();
        files.push_back({{"file", row.file},
                         {"kind", r.other_kind},
                         {"cells", s.cells},
                         {"matched", s.right},
                         {"mismatched", s.wrong},
                         {"blank", s.blank},
                         {"score_percent", s.percent ? formats::json(*s.percent) : formats::json(nullptr)},
                         {"first_divergence", first ? formats::json(worded(*first)) : formats::json(nullptr)},
                         {"first_divergence_path", first ? formats::json(first->path) : formats::json(nullptr)},
                         {"error", nullptr}});
    }
    return formats::format_json({{"reference", subject.reference},
                                 {"what", subject.what},
                                 {"tolerance", {{"rtol", subject.tolerance.rtol}, {"atol", subject.tolerance.atol}}},
                                 {"files", files}});
}

std::string summary_csv(const std::vector<ClassRow>& rows) {
    std::string text =
        "file,kind,cells,matched,mismatched,blank,score_percent,first_divergence,first_divergence_path,error\n";
    for (const ClassRow& row : rows) {
        if (!row.report) {
            text += formats::csv_row({row.file, "", "", "", "", "", "", "", "", row.error});
            continue;
        }
        const DiffReport& r = *row.report;
        const Score s = score_of(r);
        const Finding* first = r.first_divergence();
        char score[32] = "";
        if (s.percent) std::snprintf(score, sizeof score, "%.1f", *s.percent);
        text +=
            formats::csv_row({row.file, r.other_kind, count_text(s.cells), count_text(s.right), count_text(s.wrong),
                              count_text(s.blank), score, first ? worded(*first) : "", first ? first->path : "", ""});
    }
    return text;
}

std::string cells_csv(const std::vector<ClassRow>& rows, const Tolerance& tolerance) {
    std::string text = "file,place,quantity,unit,expected,found,relative_error,verdict,first_divergence,path\n";
    const auto value = [](const formats::json& v) { return v.is_structured() ? v.dump() : scalar_text(v); };
    const auto expected = [&tolerance, &value](const formats::json& v) {
        return v.is_number_float() ? formats::number_text(rounded_for_hand_work(v.get<double>(), tolerance)) : value(v);
    };
    const auto error = [](const std::optional<double>& e) {
        if (!e) return std::string();
        char digits[32];
        std::snprintf(digits, sizeof digits, "%.3g", *e);
        return std::string(digits);
    };
    for (const ClassRow& row : rows) {
        if (!row.report) {
            text += formats::csv_row({row.file, "", "", "", "", "", "", "unreadable", "", row.error});
            continue;
        }
        const DiffReport& r = *row.report;
        const Finding* first = r.first_divergence();
        if (r.other_kind == "worksheet") {
            for (const GradedNumber& g : r.graded)
                text += formats::csv_row({row.file, g.place, g.quantity, g.unit, expected(g.expected), value(g.found),
                                          error(g.relative_error), std::string(verdict_name(g.verdict)),
                                          first && first->path == g.path ? "true" : "false", g.path});
            // What the sheet was made with, where it differs: not the student's numbers, but why they may differ.
            for (const Finding& f : r.findings)
                if (f.kind == FindingKind::setting || f.kind == FindingKind::scene)
                    text +=
                        formats::csv_row({row.file, f.place, f.quantity, f.unit, expected(f.expected), value(f.found),
                                          error(f.relative_error), std::string(finding_kind_name(f.kind)),
                                          f.first_divergence ? "true" : "false", f.path});
            continue;
        }
        for (const Finding& f : r.findings)
            text += formats::csv_row({row.file, f.place, f.quantity, f.unit, expected(f.expected), value(f.found),
                                      error(f.relative_error), std::string(finding_kind_name(f.kind)),
                                      f.first_divergence ? "true" : "false", f.path});
    }
    return text;
}

std::string feedback_markdown(const ClassRow& row, const ClassSubject& subject) {
    const std::string name = std::filesystem::path(row.file).filename().string();
    std::string md = "# Feedback on " + md_text(name) + "\n\n";
    // The reference by its file's name alone: where the teacher keeps it is not the student's business.
    const std::string reference = md_text(std::filesystem::path(subject.reference).filename().string());
    const std::string against = subject.what.empty() ? reference : md_text(subject.what) + " (" + reference + ")";
    if (!row.report) {
        md += "This file could not be graded:\n\n> " + md_text(row.error) +
              "\n\nHand it in again as the worksheet was given out: the JSON file, or the CSV file with its header "
              "row (kind,path,step,quantity,value,…) and commas between the columns. A spreadsheet keeps that when "
              "you save as \"CSV (comma-separated)\".\n";
        return md;
    }
    const DiffReport& r = *row.report;
    const Score s = score_of(r);
    const bool sheet = r.other_kind == "worksheet";
    md += std::string(sheet ? "Worksheet: " : "Your engine's trace against ") + against +
          ". Every number is compared with " + std::string(subject.answer_key ? "the key's" : "the engine's own") +
          " value; it counts as right when " + tolerance_words(subject.tolerance) + ".\n\n";
    md += "**Score: " + count_text(s.right) + " of " + count_text(s.cells) +
          (sheet ? " numbers right" : " values match") + (s.percent ? " (" + percent_text(*s.percent) + ")" : "") +
          "** · " + count_text(s.wrong) + (sheet ? " wrong · " : " differ") +
          (sheet ? count_text(s.blank) + " blank" : "") + "\n\n";

    if (const Finding* first = r.first_divergence()) {
        md += "## ▶ Where it first went wrong\n\n";
        if (first->kind == FindingKind::setting || first->kind == FindingKind::scene) {
            md += "Your " + std::string(sheet ? "worksheet was made" : "trace ran") + " with a different " +
                  (first->kind == FindingKind::setting ? "setting" : "scene") + ": " + code(first->quantity) + " is " +
                  md_text(shown_value(first->found, subject.tolerance)) + " where the reference has " +
                  md_text(shown_value(first->expected, subject.tolerance)) +
                  ". Every number computed after it may differ for that reason alone: get the worksheet again.\n\n";
        } else {
            md += "**" + (first->place.empty() ? std::string("the worksheet") : first->place) + "**, " +
                  code(first->quantity) + (first->unit.empty() ? "" : " (" + first->unit + ")") + ": ";
            if (first->kind == FindingKind::value)
                md += std::string(subject.answer_key ? "the key has " : "the engine has ") +
                      md_text(shown_value(first->expected, subject.tolerance)) + ", you have " +
                      md_text(shown_value(first->found, subject.tolerance)) +
                      (first->relative_error ? " (" + how_far(first->relative_error, first->expected, first->unit) + ")"
                                             : "") +
                      ".";
            if (const std::string slip = slip_of(first->expected, first->found); !slip.empty())
                md += " That is " + slip + (slip.ends_with('?') ? "" : ".");
            else
                md += std::string(finding_kind_name(first->kind)) + ".";
            if (!first->formula.empty())
                md += " Its formula: " + first->formula + (first->equation.empty() ? "" : " " + first->equation) + ".";
            md += later_divergence(r, *first)
                      ? "\n\nThe wrong numbers after it often follow from this one: put it right first, then work the "
                        "steps after it again.\n\n"
                      : "\n\n";
        }
    } else if (s.wrong > 0) {
        md += "Every number you wrote for a cell is right the first time, but " + count_text(s.wrong) +
              (s.wrong == 1 ? " number is" : " numbers are") +
              " given again or not asked for, and count as wrong: answer each cell of the worksheet once" +
              (s.blank > 0 ? "; " + count_text(s.blank) + " left blank" : "") + ".\n\n";
    } else if (sheet && empty_sheet(r)) {
        md += "The file gives no cells: nothing of the worksheet is answered.\n\n";
    } else if (s.blank > 0) {
        md += "Every number you wrote is right; " + count_text(s.blank) + " left blank.\n\n";
    } else {
        md += "Every number is right.\n\n";
    }

    if (!sheet) {
        // A trace has thousands of values: only those that differ, under their places.
        if (!r.findings.empty())
            md += "## What differs\n\n```\n" + findings_table(r.findings, 200, subject.tolerance) + "```\n";
        if (r.findings.size() > 200)
            md += "\n… and " + count_text(r.findings.size() - 200) + " more differences (cells.csv lists them all).\n";
        return md;
    }

    // The sheet itself: what it was made with, where that differs.
    std::string made;
    for (const Finding& f : r.findings)
        if (f.kind == FindingKind::setting || f.kind == FindingKind::scene)
            made += "- " + code(f.place + "." + f.quantity) + ": yours " +
                    md_text(shown_value(f.found, subject.tolerance)) + ", the reference " +
                    md_text(shown_value(f.expected, subject.tolerance)) + "\n";
    if (!made.empty()) md += "## The worksheet you filled in\n\nIt differs from the one handed out:\n\n" + made + "\n";

    md += "## Your answers, step by step\n";
    // Each wrong or blank number's finding: the findings of one path in the order its numbers were graded.
    std::map<std::string, std::vector<const Finding*>> findings_of;
    for (const Finding& f : r.findings) findings_of[f.path].push_back(&f);
    std::map<std::string, std::size_t> used;
    const auto next_finding = [&](const std::string& path) -> const Finding* {
        const auto found = findings_of.find(path);
        if (found == findings_of.end()) return nullptr;
        std::size_t& n = used[path];
        return n < found->second.size() ? found->second[n++] : found->second.back();
    };
    std::string place = "\x01";
    std::string slips_named;  // in this step's table: a likely slip is named once, at its first number
    for (const GradedNumber& g : r.graded) {
        if (g.place != place) {
            place = g.place;
            slips_named.clear();
            md += "\n### " + (place.empty() ? std::string("elsewhere") : place) +
                  "\n\n|  | quantity | unit | expected | yours | verdict |\n|---|---|---|---|---|---|\n";
        }
        const Finding* f = g.verdict == Verdict::right ? nullptr : next_finding(g.path);
        std::string verdict(verdict_name(g.verdict));
        if (g.verdict == Verdict::wrong) {
            if (f && f->kind == FindingKind::duplicate)
                verdict += ": given again (only its first answer is graded)";
            else if (f && f->kind == FindingKind::not_asked)
                verdict += ": this worksheet does not ask for it";
            else if (g.expected.is_null())
                verdict += ": the reference has no such value";
            else if (const std::string far = how_far(g.relative_error, g.expected, g.unit); !far.empty())
                verdict += ", " + far;
            if (const std::string slip = slip_of(g.expected, g.found);
                !slip.empty() && slips_named.find(slip) == std::string::npos) {
                verdict += " — " + slip;
                slips_named += slip + "\n";
            }
            if (f && !f->formula.empty())
                verdict += " — " + f->formula + (f->equation.empty() ? "" : " " + f->equation);
        }
        const bool marked = f && f->first_divergence;
        md += "| " + std::string(marked ? "▶" : "") + " | " + md_cell(code(g.quantity)) + " | " + md_cell(g.unit) +
              " | " + md_cell(shown_value(g.expected, subject.tolerance)) + " | " +
              (g.found.is_null() ? "" : md_text(scalar_text(g.found))) + " | " +
              md_cell(marked ? "**" + verdict + "**" : verdict) + " |\n";
    }
    return md;
}

std::vector<std::string> feedback_names(const std::vector<std::string>& files) {
    std::map<std::string, int> stems;
    for (const std::string& f : files) ++stems[std::filesystem::path(f).stem().string()];
    std::vector<std::string> names;
    std::map<std::string, int> used;
    for (const std::string& f : files) {
        const std::filesystem::path p(f);
        std::string name = stems[p.stem().string()] > 1 ? p.filename().string() : p.stem().string();
        // Files of the same name in different folders: the second is name-2.md, and so on.
        if (const int n = ++used[name]; n > 1) name += "-" + std::to_string(n);
        names.push_back(name + ".md");
    }
    return names;
}

}  // namespace impulse::course
