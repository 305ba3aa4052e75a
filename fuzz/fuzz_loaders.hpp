#pragma once
// The loaders the fuzz targets drive, each taking the whole input as text. Shared with the regression test
// (tests/course/test_fuzz_regressions.cpp), which feeds every kept crasher to the same function. A loader given
// bad input throws formats::InputError; anything else (another exception, a crash, a sanitizer report, a hang,
// a runaway allocation) is a bug. No loader writes a file or reads one.

#include "course/class_report.hpp"
#include "course/filled_worksheet.hpp"
#include "course/worksheet.hpp"
#include "formats/input_error.hpp"
#include "formats/input_files.hpp"
#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "formats/trace_json.hpp"
#include "course/lesson.hpp"
#include "model/session.hpp"
#include "course/progress.hpp"

#include <string_view>

namespace impulse::fuzz {

// A case or scene file (docs/scenes.md), as `resolve`, `run` and `inspect` read it.
inline void load_scene_text(std::string_view text) {
    formats::read_scene_text(text);
}

// A trace file (docs/trace-format.md), as `inspect` and `diff` read it.
inline void load_trace_text(std::string_view text) {
    formats::read_trace_text(text);
}

// A lesson's Markdown with its JSON header (docs/lessons.md); the scene it names is not opened.
inline void load_lesson_text(std::string_view text) {
    course::read_lesson_text(text, "01-fuzz.md");
}

// A filled worksheet (docs/coursework.md) as `diff` reads a student's sheet, JSON or CSV.
inline void load_worksheet_json(std::string_view text) {
    course::read_worksheet_json(formats::parse_json_text(text));
}
inline void load_worksheet_csv(std::string_view text) {
    course::read_worksheet_csv(text);
}

// A worksheet as the reference of `diff`: its settings and scene are read and its trace re-run.
inline void load_worksheet_reference(std::string_view text) {
    course::rerun_reference(formats::parse_json_text(text));
}

// A student's progress file's content (the file in the user's config folder is never opened).
inline void load_progress_text(std::string_view text) {
    course::read_progress_text(text);
}

// `diff` on two inputs, in memory: the reference trace, a NUL byte, then the other file: a trace or a JSON
// worksheet when it starts with "{", else a CSV worksheet. The reference is read and written back as `diff`
// does with a trace it is given, the other goes through the checks of diff_command.cpp, then the comparison
// and its three reports, worded as the worksheet words them, and the class report of it. Without a NUL there is
// nothing to compare.
inline void load_diff(std::string_view input) {
    const std::size_t separator = input.find('\0');
    if (separator == std::string_view::npos) return;
    const Trace trace = formats::read_trace_text(input.substr(0, separator));
    const formats::json reference = formats::trace_json(trace);
    const std::string_view other = input.substr(separator + 1);
    const course::Tolerance tolerance;
    const std::size_t first = other.find_first_not_of(" \t\r\n");
    course::DiffReport report;
    if (first == std::string_view::npos || other[first] != '{') {
        report = course::diff_worksheet(reference, course::read_worksheet_csv(other), tolerance);
    } else {
        const formats::json document = formats::parse_json_text(other);
        if (course::is_worksheet(document)) {
            report = course::diff_worksheet(reference, course::read_worksheet_json(document), tolerance);
        } else {
            formats::read_trace(document);
            report = course::diff_traces(reference, document, tolerance);
        }
    }
    course::word_findings(report, trace, reference);
    const course::DiffSubject subject{"reference.json", "other", tolerance};
    course::report_text(report, subject);
    course::report_json(report, subject);
    course::report_csv(report);
    const std::vector<course::ClassRow> rows{{"other", report, ""}};
    const course::ClassSubject class_subject{"reference.json", "trace", tolerance};
    course::summary_text(rows, class_subject);
    course::summary_json(rows, class_subject);
    course::summary_csv(rows);
    course::cells_csv(rows, tolerance);
    course::feedback_markdown(rows.front(), class_subject);
}

// A trace as `worksheet` reads it: opened as a session, its default places chosen and the worksheet made and
// written in both forms. A trace the reader accepts must make a worksheet or be refused in words (one whose
// iteration number was changed to 2147483647 passed `validate` and made `worksheet` segfault).
inline void load_worksheet_trace(std::string_view text) {
    const model::Session session = [&] {
        try {
            return model::Session::open_text(std::string(text), "fuzz.trace.json", {});
        } catch (const formats::FileError& e) {  // the session names the file: bad input all the same
            throw formats::InputError(e.where, e.problem);
        }
    }();
    if (session.broken_run()) return;
    const Trace& trace = session.trace();
    const formats::json document = formats::trace_json(trace);
    const std::vector<model::Cursor> places = course::default_places(trace, &document);
    if (places.empty()) return;
    const course::Worksheet sheet = course::make_worksheet(session, places, &document);
    course::worksheet_csv(sheet);
    course::worksheet_json(sheet);
}

struct Loader {
    std::string_view target;  // the fuzz target, and its folder under tests/fuzz_regressions
    void (*load)(std::string_view text);
};

inline constexpr Loader loaders[] = {
    {"fuzz_scene_text", load_scene_text},           {"fuzz_trace_text", load_trace_text},
    {"fuzz_lesson_text", load_lesson_text},         {"fuzz_worksheet_json", load_worksheet_json},
    {"fuzz_worksheet_csv", load_worksheet_csv},     {"fuzz_worksheet_reference", load_worksheet_reference},
    {"fuzz_progress_text", load_progress_text},     {"fuzz_diff", load_diff},
    {"fuzz_worksheet_trace", load_worksheet_trace},
};

}  // namespace impulse::fuzz
