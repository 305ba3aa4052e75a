// `impulse-lab worksheet FILE --out sheet.json|.csv`: the inputs and blank cells of chosen derivation steps
// of a lesson, case, scene or trace, for students to fill in by hand or with their own engine (docs/coursework.md).

#include "io/trace_json.hpp"
#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "cli/input_files.hpp"
#include "coursework/worksheet.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/json_text.hpp"
#include "lessons/lesson.hpp"

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
    const bool csv = ends_with_case_blind(options.out, ".csv");
    if (!csv && !ends_with_case_blind(options.out, ".json"))
        throw io::InputError("--out", "must end in .json or .csv, got \"" + options.out + "\"");
    io::check_writable(options.out, "--out");

    // A lesson (NN-name.md) gives its run and, unless --steps says otherwise, its steps' places: those that
    // compute something to fill in (a step that only shows a choice has no cells).
    std::optional<lessons::PreparedLesson> lesson;
    if (ends_with_case_blind(options.file, ".md")) {
        if (options.open.preset || !options.open.settings.empty() || !options.open.record.empty() ||
            options.open.frames || options.open.max_trace_mb)
            throw io::InputError("worksheet",
                                 "a lesson runs with its own settings; give its scene file to change "
                                 "them");
        lesson.emplace(lessons::prepare_lesson(lessons::read_lesson(options.file)));
    }
    const inspect::Session session = lesson ? lesson->session : inspect::Session::open(options.file, options.open);
    if (session.trace().version != trace_format_version) err << io::format1_note(options.file) << '\n';
    if (session.recording_stopped_at())
        err << trace_stopped_note(*session.recording_stopped_at(), options.open.max_trace_mb) << '\n';
    // A worksheet's numbers must be re-made exactly by diff; a run that broke is not coursework.
    if (session.broken_run()) {
        err << "impulse-lab: " << inspect::broken_run_text(session.trace().scene, *session.broken_run())
            << "; no worksheet written\n";
        return exit_non_finite;
    }
    const Trace& trace = session.trace();
    std::vector<inspect::Cursor> places;
    if (!options.steps.empty())
        places = coursework::places_from_specs(trace, options.steps, "--steps");
    else if (lesson) {
        for (const inspect::Cursor& place : lesson->places) try {
                coursework::make_worksheet(session, {place});
                places.push_back(place);
            } catch (const io::InputError&) {
                // nothing to fill in at this step
            }
    } else
        places = coursework::default_places(trace);
    if (places.empty())
        throw FileError{options.file, "", "the recording has no contact, so there is nothing to fill in"};
    const coursework::Worksheet sheet = coursework::make_worksheet(session, places);

    io::write_file_atomically(
        options.out, csv ? coursework::worksheet_csv(sheet) : io::format_json(coursework::worksheet_json(sheet)),
        "--out");
    std::size_t cells = 0, numbers = 0, inputs = 0;
    for (const coursework::WorksheetStep& step : sheet.steps) {
        cells += step.cells.size();
        inputs += step.inputs.size();
        for (const coursework::WorksheetEntry& cell : step.cells)
            coursework::for_each_scalar(cell.value, "", [&numbers](const std::string&, const io::json&) { ++numbers; });
    }
    out << "worksheet written to " << options.out << ": " << sheet.steps.size()
        << (sheet.steps.size() == 1 ? " step, " : " steps, ") << cells << " cells (" << numbers
        << " values to fill in), " << inputs << " inputs given\n";
    return 0;
}

}  // namespace impulse::cli
