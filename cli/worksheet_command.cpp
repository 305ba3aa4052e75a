// `impulse-lab worksheet FILE --out sheet.json|.csv`: the inputs and blank cells of chosen derivation steps
// of a lesson, case, scene or trace, for students to fill in by hand or with their own engine (docs/coursework.md).

#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "cli/data_folder.hpp"
#include "formats/input_files.hpp"
#include "course/worksheet.hpp"
#include "cli/outputs.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/trace_format1.hpp"
#include "formats/trace_json.hpp"
#include "course/lesson.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

namespace impulse::cli {

namespace {

bool ends_with_case_blind(std::string_view text, std::string_view end) {
    return text.size() >= end.size() &&
           std::equal(end.begin(), end.end(), text.end() - static_cast<std::ptrdiff_t>(end.size()),
                      [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

}  // namespace

int worksheet_command(const WorksheetOptions& options, std::ostream& out, std::ostream& err) {
    // Standard output gets JSON; a file's name says which.
    Outputs outputs(out, err);
    const bool to_standard_output = names_standard_output(options.out, out);
    const bool csv = !to_standard_output && ends_with_case_blind(options.out, ".csv");
    if (!to_standard_output && !csv && !ends_with_case_blind(options.out, ".json"))
        throw formats::InputError(
            "--out", "must end in .json or .csv (or be - for standard output), got \"" + options.out + "\"");
    // A lesson may be named by its number: `worksheet 7`.
    const std::string file = lesson_or_file(options.file, "worksheet");
    DistinctFiles files;
    files.input("the worksheet's FILE", file);
    files.output("--out", options.out);
    outputs.add("--out", options.out);
    std::ostream& report = outputs.report();

    // A lesson (NN-name.md) gives its run and, unless --steps says otherwise, its steps' places: those that
    // compute something to fill in (a step that only shows a choice has no cells).
    std::optional<course::PreparedLesson> lesson;
    if (ends_with_case_blind(file, ".md")) {
        if (options.open.preset || !options.open.settings.empty() || !options.open.record.empty() ||
            options.open.frames || options.open.max_trace_mb)
            throw formats::InputError("worksheet",
                                      "a lesson runs with its own settings; give its scene file to change "
                                      "them");
        lesson.emplace(course::prepare_lesson(course::read_lesson(file)));
    }
    const model::Session session = lesson ? lesson->session : model::Session::open(file, options.open);
    if (session.trace().version != trace_format_version) err << formats::format1_note(file) << '\n';
    if (const auto note = session.recording_note())
        err << "impulse-lab: note: " << *note << "; raise --max-trace-mb or narrow --record to see later frames\n";
    // A worksheet's numbers must be re-made exactly by diff; a run that broke is not coursework.
    if (session.broken_run()) {
        err << "impulse-lab: " << model::broken_run_text(session.trace().scene, *session.broken_run())
            << "; no worksheet written\n";
        return exit_non_finite;
    }
    const Trace& trace = session.trace();
    const formats::json document = formats::trace_json(trace);
    std::vector<model::Cursor> places;
    if (!options.steps.empty())
        places = course::places_from_specs(trace, options.steps, "--steps", &document);
    else if (lesson)
        places = course::places_with_cells(session, lesson->places, &document);  // a choice has no cells
    else
        places = course::default_places(trace, &document);
    if (places.empty())
        throw formats::FileError{formats::input_name(file), "",
                                 "the recording has no contact, so there is nothing to fill in"};
    const course::Worksheet sheet = course::make_worksheet(session, places, &document);

    outputs.write(
        {{"--out", csv ? course::worksheet_csv(sheet) : formats::format_json(course::worksheet_json(sheet))}});
    // The counts as the sheet shows them: a CSV sheet has a row per number and each input once, a JSON sheet an
    // entry per cell and per input of each step.
    const course::WorksheetCounts counts = csv ? course::csv_counts(sheet) : course::json_counts(sheet);
    const auto plural = [](std::size_t n, const char* one, const char* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    report << "worksheet written to " << (to_standard_output ? "standard output" : options.out) << ": "
           << plural(sheet.steps.size(), "step", "steps") << ", "
           << (csv ? plural(counts.numbers, "row", "rows") + " to fill in, " +
                         plural(counts.inputs, "input row", "input rows")
                   : plural(counts.cells, "cell", "cells") + " (" + plural(counts.numbers, "number", "numbers") +
                         " to fill in), " + plural(counts.inputs, "input", "inputs") + " given over its steps")
           << '\n';
    return 0;
}

}  // namespace impulse::cli
