// `impulse-lab diff REFERENCE OTHER...`: compare traces or filled worksheets with a reference, value by value
// (docs/coursework.md). One OTHER: every mismatch. Several (or a folder): a class summary, one row per file.

#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "cli/input_files.hpp"
#include "coursework/diff_report.hpp"
#include "coursework/worksheet.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/json_text.hpp"
#include "io/trace_json.hpp"
#include "model/session.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace impulse::cli {

namespace {

bool is_csv(const std::string& file) {
    std::string extension = std::filesystem::path(file).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".csv";
}

coursework::DiffReport diff_file(const io::json& reference, const std::string& file,
                                 const coursework::Tolerance& tolerance, std::ostream& err) {
    const std::string text = read_input_file(file);
    try {
        if (is_csv(file)) return coursework::diff_worksheet(reference, coursework::read_worksheet_csv(text), tolerance);
        io::json document = io::parse_json_text(text);
        if (coursework::is_worksheet(document))
            return coursework::diff_worksheet(reference, coursework::read_worksheet_json(document), tolerance);
        if (document.is_object() && document.contains("format") && document["format"] == io::trace_format_name) {
            // A format-1 trace is compared in today's words: its renamed keys moved first.
            if (io::upgrade_trace_document(document)) err << io::format1_note(file) << '\n';
            io::read_trace(document);  // its schema, and that every index names a body or contact
            return coursework::diff_traces(reference, document, tolerance);
        }
        const bool has_format = document.is_object() && document.contains("format");
        throw io::InputError(has_format ? "format" : "",
                             std::string(has_format ? "" : "no \"format\": ") + "expected a trace (\"" +
                                 std::string(io::trace_format_name) + "\") or a worksheet (\"" +
                                 std::string(coursework::worksheet_format_name) + "\")" +
                                 (has_format ? ", got " + document["format"].dump() : ""));
    } catch (const io::InputError& e) {
        throw FileError{file, e.where(), e.problem()};
    }
}

// The files named: a folder stands for the .json and .csv files in it, by name.
std::vector<std::string> files_named(const std::vector<std::string>& others, bool& folder) {
    std::vector<std::string> files;
    for (const std::string& other : others) {
        std::error_code error;
        if (!std::filesystem::is_directory(other, error)) {
            files.push_back(other);
            continue;
        }
        folder = true;
        std::vector<std::string> inside;
        for (const auto& entry : std::filesystem::directory_iterator(other, error)) {
            const std::string extension = entry.path().extension().string();
            if (entry.is_regular_file(error) && (extension == ".json" || is_csv(entry.path().string())))
                inside.push_back(entry.path().string());
        }
        if (inside.empty()) throw FileError{other, "", "is a folder without .json or .csv files to compare"};
        std::sort(inside.begin(), inside.end());
        files.insert(files.end(), inside.begin(), inside.end());
    }
    return files;
}

// The reference: a case or scene run as `inspect` runs it, a trace, or a worksheet re-run from what it was
// made from.
inspect::Session open_reference(const DiffOptions& o) {
    const std::string text = read_input_file(o.reference);
    io::json document;
    try {
        document = io::parse_json_text(text);
        if (coursework::is_worksheet(document)) {
            if (const auto flag = o.open.first_given())
                throw io::InputError(std::string(*flag),
                                     "a worksheet reference is re-run as it was made; give the case or scene to "
                                     "run it differently");
            return inspect::Session::from_trace(coursework::rerun_reference(document), inspect::SourceKind::trace_file,
                                                o.reference);
        }
    } catch (const io::InputError& e) {
        if (e.where().starts_with("--")) throw;
        throw FileError{o.reference, e.where(), e.problem()};
    }
    return inspect::Session::open(o.reference, o.open);
}

void check_tolerance(double value, const char* flag) {
    if (!std::isfinite(value) || value < 0)
        throw io::InputError(flag, "must be a number >= 0, got " + io::number_text(value));
}

}  // namespace

int diff_command(const DiffOptions& options, std::ostream& out, std::ostream& err) {
    check_tolerance(options.rtol, "--rtol");
    check_tolerance(options.atol, "--atol");
    const coursework::Tolerance tolerance{options.rtol, options.atol};
    if (options.out) io::check_writable(*options.out, "--out");

    const inspect::Session session = open_reference(options);
    const io::json reference = io::trace_json(session.trace());
    bool folder = false;
    const std::vector<std::string> files = files_named(options.others, folder);

    std::string report;
    int code = exit_ok;
    if (files.size() == 1 && !folder) {
        // One file: its every mismatch; a file that cannot be read is bad input.
        const coursework::DiffReport r = diff_file(reference, files.front(), tolerance, err);
        const coursework::DiffSubject subject{options.reference, files.front(), tolerance};
        report = options.format == "json"  ? coursework::report_json(r, subject)
                 : options.format == "csv" ? coursework::report_csv(r)
                                           : coursework::report_text(r, subject);
        code = r.all_match() ? exit_ok : exit_failure;
    } else {
        // A class: one row per file; a file that cannot be read gets its row (and a line here) and does not stop
        // the others.
        std::vector<coursework::ClassRow> rows;
        for (const std::string& file : files) {
            try {
                rows.push_back({file, diff_file(reference, file, tolerance, err), ""});
                if (!rows.back().report->all_match()) code = exit_failure;
            } catch (const FileError& e) {
                const std::string error = (e.where.empty() ? "" : e.where + ": ") + e.problem;
                err << "impulse-lab: " << e.file << ": " << error << '\n';
                rows.push_back({file, std::nullopt, error});
                code = exit_failure;
            }
        }
        report = options.format == "json"  ? coursework::summary_json(rows, options.reference, tolerance)
                 : options.format == "csv" ? coursework::summary_csv(rows)
                                           : coursework::summary_text(rows, options.reference, tolerance);
    }
    if (options.out) io::write_file_atomically(*options.out, report, "--out");
    out << report;
    return code;
}

}  // namespace impulse::cli
