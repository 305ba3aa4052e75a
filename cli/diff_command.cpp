// `impulse-lab diff REFERENCE OTHER...`: compare traces or filled worksheets with a reference, value by value
// (docs/coursework.md). One OTHER: every mismatch. Several (or a folder): a class summary, one row per file, and
// with --out DIR the class report: summary.csv, cells.csv and a feedback page per student.

#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "cli/data_folder.hpp"
#include "formats/input_files.hpp"
#include "cli/outputs.hpp"
#include "course/class_report.hpp"
#include "course/worksheet.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/trace_format1.hpp"
#include "formats/trace_json.hpp"
#include "course/lesson.hpp"
#include "model/session.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace impulse::cli {

namespace {

namespace fs = std::filesystem;

std::string lowered_extension(const std::string& file) {
    std::string extension = fs::path(file).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

bool is_csv(const std::string& file) {
    return lowered_extension(file) == ".csv";
}

// A worksheet on standard input has no name to tell CSV by: JSON starts with "{".
bool is_csv_text(const std::string& file, const std::string& text) {
    if (file != formats::standard_stream) return is_csv(file);
    const std::size_t first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    return first == std::string::npos || text[first] != '{';
}

// What the class is graded against: the reference run (none for an answer key), its trace document, and — when
// the reference is a lesson or a worksheet — the cells the worksheet was handed out with.
struct Reference {
    std::optional<model::Session> session;
    formats::json document;
    std::optional<std::vector<std::string>> asked;
    std::string what;                            // for the reports' headers
    std::optional<course::FilledWorksheet> key;  // an answer key (a filled CSV sheet): its own words
};

std::vector<std::string> cell_paths(const course::Worksheet& sheet) {
    std::vector<std::string> paths;
    for (const course::WorksheetStep& step : sheet.steps)
        for (const course::WorksheetEntry& cell : step.cells) paths.push_back(cell.path);
    return paths;
}

// An answer key: a CSV worksheet filled in, given as the reference. Its cells are what was handed out and its
// values the expected ones; there is nothing to re-run.
Reference open_answer_key(const DiffOptions& o, const std::string& file, const std::string& text) {
    if (const auto flag = o.open.first_given())
        throw formats::InputError(std::string(*flag),
                                  "a CSV reference is an answer key: its values are the expected ones, there is "
                                  "nothing to run");
    try {
        course::FilledWorksheet key = course::read_worksheet_csv(text);
        if (key.cells.empty()) throw formats::InputError("", "has no cells to grade against");
        formats::json document = course::answer_key_document(key);
        std::vector<std::string> asked;
        for (const course::FilledCell& cell : key.cells) asked.push_back(cell.path);
        return {std::nullopt, std::move(document), std::move(asked), "answer key", std::move(key)};
    } catch (const formats::InputError& e) {
        throw formats::FileError{formats::input_name(file), e.where(), e.problem()};
    }
}

// The reference: a lesson run as `worksheet` runs it (its worksheet is what was handed out; a lesson may be named
// by its number), a worksheet re-run from what it was made from, an answer key (a filled CSV sheet), a case or
// scene run as `inspect` runs it, or a trace.
Reference open_reference(const DiffOptions& o, const std::string& file) {
    if (lowered_extension(file) == ".md") {
        if (const auto flag = o.open.first_given())
            throw formats::InputError(std::string(*flag),
                                      "a lesson runs with its own settings; give its scene file to run it differently");
        course::PreparedLesson lesson = course::prepare_lesson(course::read_lesson(file));
        formats::json document = formats::trace_json(lesson.session.trace());
        const std::vector<model::Cursor> places = course::places_with_cells(lesson.session, lesson.places, &document);
        std::vector<std::string> asked = cell_paths(course::make_worksheet(lesson.session, places, &document));
        const std::string what = "lesson " + std::to_string(lesson.lesson.number) + " · " + lesson.lesson.title;
        return {std::move(lesson.session), std::move(document), std::move(asked), what, std::nullopt};
    }
    const std::string text = formats::read_input_file(file);
    if (is_csv_text(file, text)) return open_answer_key(o, file, text);
    try {
        const formats::json document = formats::parse_json_text(text);
        if (course::is_worksheet(document)) {
            if (const auto flag = o.open.first_given())
                throw formats::InputError(std::string(*flag),
                                          "a worksheet reference is re-run as it was made; give the case or scene to "
                                          "run it differently");
            std::vector<std::string> asked;
            for (const course::FilledCell& cell : course::read_worksheet_json(document).cells)
                asked.push_back(cell.path);
            model::Session session =
                model::Session::from_trace(course::rerun_reference(document), model::SourceKind::trace_file, file);
            formats::json trace = formats::trace_json(session.trace());
            return {std::move(session), std::move(trace), std::move(asked), "worksheet", std::nullopt};
        }
    } catch (const formats::InputError& e) {
        if (e.where().starts_with("--")) throw;
        throw formats::FileError{formats::input_name(file), e.where(), e.problem()};
    }
    model::Session session = model::Session::open_text(text, file, o.open);
    formats::json trace = formats::trace_json(session.trace());
    const std::string what = session.kind() == model::SourceKind::case_file    ? "case"
                             : session.kind() == model::SourceKind::scene_file ? "scene"
                                                                               : "trace";
    return {std::move(session), std::move(trace), std::nullopt, what, std::nullopt};
}

course::DiffReport diff_file(const Reference& reference, const std::string& file, const course::Tolerance& tolerance,
                             std::ostream& err) {
    const std::string text = formats::read_input_file(file);
    try {
        course::DiffReport report;
        const std::vector<std::string>* asked = reference.asked ? &*reference.asked : nullptr;
        if (is_csv_text(file, text)) {
            report = course::diff_worksheet(reference.document, course::read_worksheet_csv(text), tolerance, asked);
        } else {
            formats::json document = formats::parse_json_text(text);
            if (course::is_worksheet(document)) {
                report =
                    course::diff_worksheet(reference.document, course::read_worksheet_json(document), tolerance, asked);
            } else if (document.is_object() && document.contains("format") &&
                       document["format"] == formats::trace_format_name) {
                if (reference.key)
                    throw formats::InputError("",
                                              "a trace is compared with a trace, case, scene, lesson or "
                                              "worksheet it ran from, not with an answer key");
                // A format-1 trace is compared in today's words: its renamed keys moved first.
                if (formats::upgrade_trace_document(document)) err << formats::format1_note(file) << '\n';
                formats::read_trace(document);  // its schema, and that every index names a body or contact
                report = course::diff_traces(reference.document, document, tolerance);
            } else {
                const bool has_format = document.is_object() && document.contains("format");
                throw formats::InputError(has_format ? "format" : "",
                                          std::string(has_format ? "" : "no \"format\": ") + "expected a trace (\"" +
                                              std::string(formats::trace_format_name) + "\") or a worksheet (\"" +
                                              std::string(course::worksheet_format_name) + "\")" +
                                              (has_format ? ", got " + document["format"].dump() : ""));
            }
        }
        if (reference.key)
            course::word_findings_by_key(report, *reference.key);
        else
            course::word_findings(report, reference.session->trace(), reference.document);
        return report;
    } catch (const formats::InputError& e) {
        throw formats::FileError{formats::input_name(file), e.where(), e.problem()};
    }
}

// A file named, and why it is not read when a folder holds something other than a worksheet or trace.
struct Submission {
    std::string file;
    std::string not_read;
};

// The files named: a folder stands for every file in it (sorted by name, not recursive), except hidden files and
// sub-folders. Only .json and .csv files are read; any other file in a folder gets its row saying so, so a
// spreadsheet saved in its own format is not silently left out.
std::vector<Submission> files_named(const std::vector<std::string>& others, bool& folder) {
    std::vector<Submission> files;
    for (const std::string& other : others) {
        std::error_code error;
        if (!fs::is_directory(other, error)) {
            files.push_back({other, ""});
            continue;
        }
        folder = true;
        // Every entry gets its row or is skipped for a stated reason, whatever order the folder lists them in: a
        // link that points nowhere was once the whole folder's error, or no row at all.
        std::vector<Submission> inside;
        fs::directory_iterator it(other, error);
        if (error) throw formats::FileError{other, "", "cannot list the folder: " + error.message()};
        for (; it != fs::directory_iterator(); it.increment(error)) {
            if (error) throw formats::FileError{other, "", "cannot list the folder: " + error.message()};
            const fs::path path = it->path();
            if (path.filename().string().starts_with(".")) continue;
            std::error_code kind;
            const fs::file_status status = fs::status(path, kind);  // through links
            if (fs::is_directory(status)) continue;
            const std::string extension = lowered_extension(path.string());
            const bool link = fs::is_symlink(fs::symlink_status(path, kind));
            inside.push_back(
                {path.string(),
                 fs::is_regular_file(status)
                     ? (extension == ".json" || extension == ".csv"
                            ? ""
                            : "not a worksheet or trace: only .json and .csv files are read (save a spreadsheet as "
                              "CSV, comma-separated)")
                 : link && !fs::exists(status)
                     ? "a link to " + fs::read_symlink(path, kind).string() + ", which does not exist"
                     : "not a file (a FIFO, a socket or a device): not read"});
        }
        if (inside.empty()) throw formats::FileError{other, "", "is a folder without files to compare"};
        std::sort(inside.begin(), inside.end(),
                  [](const Submission& a, const Submission& b) { return a.file < b.file; });
        files.insert(files.end(), inside.begin(), inside.end());
    }
    return files;
}

void check_tolerance(double value, const char* flag) {
    if (!std::isfinite(value) || value < 0)
        throw formats::InputError(flag, "must be a number >= 0, got " + formats::number_text(value));
}

// --out for a class: a folder (created, its parent must exist), never an existing file.
void check_report_folder(const fs::path& folder) {
    std::error_code error;
    if (folder.empty()) throw formats::InputError("--out", "empty folder name");
    if (folder == formats::standard_stream)
        throw formats::InputError("--out",
                                  "with several files --out is a folder for summary.csv, cells.csv and the feedback "
                                  "pages, and '-' (standard output) is not a folder (--format csv prints the summary)");
    if (fs::exists(folder, error) && !fs::is_directory(folder, error))
        throw formats::InputError("--out",
                                  "with several files --out is a folder for summary.csv, cells.csv and the "
                                  "feedback pages, and '" +
                                      folder.string() + "' is a file");
    const std::string extension = lowered_extension(folder.string());
    if (extension == ".csv" || extension == ".json" || extension == ".txt" || extension == ".md")
        throw formats::InputError("--out",
                                  "with several files --out is a folder for summary.csv, cells.csv and the "
                                  "feedback pages, got '" +
                                      folder.string() + "', a file name (--format csv prints the summary alone)");
    const fs::path parent = folder.has_parent_path() ? folder.parent_path() : fs::path(".");
    if (!fs::is_directory(parent, error))
        throw formats::InputError("--out", "cannot create '" + folder.string() + "': No such file or directory");
}

// The class report, staged and renamed into place together: summary.csv, cells.csv, feedback/NAME.md.
void write_class_report(const fs::path& folder, const std::vector<course::ClassRow>& rows,
                        const course::ClassSubject& subject) {
    std::vector<std::string> names;
    for (const course::ClassRow& row : rows) names.push_back(row.file);
    const std::vector<std::string> pages = course::feedback_names(names);

    std::vector<std::pair<fs::path, std::string>> texts{
        {folder / "summary.csv", course::summary_csv(rows)},
        {folder / "cells.csv", course::cells_csv(rows, subject.tolerance)}};
    for (std::size_t i = 0; i < rows.size(); ++i)
        texts.emplace_back(folder / "feedback" / pages[i], course::feedback_markdown(rows[i], subject));

    const formats::HeldInterruptions held;  // Ctrl-C waits until every file is in place (or none is)
    std::error_code error;
    fs::create_directories(folder / "feedback", error);
    if (error)
        throw formats::InputError("--out",
                                  "cannot create '" + (folder / "feedback").string() + "': " + error.message());
    // Whatever would stop a rename (a folder where a file goes) stops the report before any file is replaced.
    for (const auto& [path, text] : texts) formats::check_writable(path, "--out");
    std::vector<formats::StagedFile> files;
    for (const auto& [path, text] : texts) files.emplace_back(path, text, "--out");
    for (formats::StagedFile& f : files) f.commit();
}

}  // namespace

int diff_command(const DiffOptions& options, std::ostream& out, std::ostream& err) {
    check_tolerance(options.rtol, "--rtol");
    check_tolerance(options.atol, "--atol");
    const course::Tolerance tolerance{options.rtol, options.atol};
    bool folder = false;
    const std::vector<Submission> files = files_named(options.others, folder);
    const bool whole_class = files.size() > 1 || folder;
    // One file's report goes to standard output anyway: `--out -` (or /dev/stdout) asks for nothing more.
    const bool out_is_file = options.out && !whole_class && !names_standard_output(*options.out, out);
    if (options.out) {
        if (whole_class)
            check_report_folder(*options.out);
        else if (out_is_file)
            formats::check_writable(*options.out, "--out");
    }

    // No report may replace the reference, a handed-in file, or another report file.
    const std::string reference_file = lesson_or_file(options.reference, "diff");
    DistinctFiles distinct;
    distinct.input("the reference REFERENCE", reference_file);
    for (const std::string& other : options.others) distinct.input("OTHER '" + other + "'", other);
    for (const Submission& s : files) distinct.input("the handed-in file '" + s.file + "'", s.file);
    if (options.out && whole_class) {
        const fs::path folder(*options.out);
        distinct.output("--out", folder.string());
        std::vector<std::string> names;
        for (const Submission& s : files) names.push_back(formats::input_name(s.file));
        distinct.output("--out", (folder / "summary.csv").string());
        distinct.output("--out", (folder / "cells.csv").string());
        for (const std::string& page : course::feedback_names(names))
            distinct.output("--out", (folder / "feedback" / page).string());
    } else if (out_is_file) {
        distinct.output("--out", *options.out);
    }
    const Reference reference = open_reference(options, reference_file);
    if (!whole_class) {
        // One file: its every mismatch; a file that cannot be read is bad input.
        const course::DiffReport r = diff_file(reference, files.front().file, tolerance, err);
        const course::DiffSubject subject{formats::input_name(options.reference),
                                          formats::input_name(files.front().file), tolerance};
        const std::string report = options.format == "json"  ? course::report_json(r, subject)
                                   : options.format == "csv" ? course::report_csv(r)
                                                             : course::report_text(r, subject);
        if (out_is_file) formats::write_file_atomically(*options.out, report, "--out");
        out << report;
        return r.all_match() ? exit_ok : exit_verdict;
    }

    // A class: one row per file; a file that cannot be read gets its row (and a line here) and does not stop
    // the others.
    std::vector<course::ClassRow> rows;
    int code = exit_ok;
    for (const Submission& s : files) {
        try {
            if (!s.not_read.empty()) throw formats::FileError{s.file, "", s.not_read};
            rows.push_back({formats::input_name(s.file), diff_file(reference, s.file, tolerance, err), ""});
            if (!rows.back().report->all_match()) code = exit_verdict;
        } catch (const formats::FileError& e) {
            const std::string error = (e.where.empty() ? "" : e.where + ": ") + e.problem;
            err << error_line(e);
            rows.push_back({formats::input_name(s.file), std::nullopt, error});
            code = exit_verdict;
        }
    }
    const course::ClassSubject subject{formats::input_name(options.reference), reference.what, tolerance,
                                       reference.key.has_value()};
    if (options.out) write_class_report(*options.out, rows, subject);
    out << (options.format == "json"  ? course::summary_json(rows, subject)
            : options.format == "csv" ? course::summary_csv(rows)
                                      : course::summary_text(rows, subject));
    if (options.out && options.format == "text")
        out << "class report written to " << *options.out << ": summary.csv, cells.csv and " << rows.size()
            << (rows.size() == 1 ? " feedback page" : " feedback pages") << " in feedback/\n";
    return code;
}

}  // namespace impulse::cli
