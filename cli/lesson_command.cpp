// `impulse-lab lesson [N]`: the course. Without N, the lessons with their titles and the student's progress;
// with N, the lesson in the inspector's window; with --text (or no display but a terminal on standard input)
// asked in the terminal; headless (or with neither) as annotated text with the answers, plus the trace and one
// screenshot per step in a folder.

#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "cli/data_folder.hpp"
#include "formats/input_files.hpp"
#include "cli/outputs.hpp"
#include "explain/text_table.hpp"
#include "gui/display.hpp"
#include "gui/inspector_app.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"
#include "course/lesson.hpp"
#include "course/progress.hpp"
#include "course/text_lesson.hpp"
#include "model/script.hpp"

#include <cstdio>

#include <sys/ioctl.h>
#include <unistd.h>

namespace impulse::cli {

namespace {

// Columns of the terminal the lesson is written to (100 when it is not one).
int terminal_width() {
    winsize size{};
    if (::ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    return 100;
}

std::filesystem::path lessons_folder(const LessonOptions& options) {
    return options.lessons_folder ? std::filesystem::path(*options.lessons_folder) : shipped_lessons_folder();
}

int list_lessons(const LessonOptions& options, const course::Progress& progress, std::ostream& out, std::ostream& err) {
    const std::filesystem::path folder = lessons_folder(options);
    const std::vector<std::filesystem::path> files = course::lesson_files(folder);
    if (files.empty()) throw formats::FileError{folder.string(), "", "no lesson files (NN-name.md) in this folder"};
    out << "Lessons in " << folder.string() << " (open one with: impulse-lab lesson N)\n";
    int status = 0;
    for (const std::filesystem::path& file : files) {
        try {
            const course::Lesson lesson = course::read_lesson(file);
            const int questions = course::question_count(lesson);
            std::optional<course::Tally> tally;
            if (const auto p = progress.lessons.find(lesson.name); p != progress.lessons.end())
                tally = course::tally(p->second);
            // Padded by what a terminal shows, not by bytes: titles hold symbols such as ×.
            const std::size_t width = explain::display_width(lesson.title);
            char line[96];
            std::snprintf(line, sizeof line, " %2zu steps, %d questions   ", lesson.steps.size(), questions);
            out << (lesson.number < 10 ? "   " : "  ") << lesson.number << "  " << lesson.title
                << std::string(width < 60 ? 60 - width : 1, ' ') << line;
            if (!tally)
                out << "not started\n";
            else
                out << course::tally_text(*tally) << '\n';
        } catch (const formats::FileError& e) {
            err << "impulse-lab: " << e.file << ": " << (e.where.empty() ? "" : e.where + ": ") << e.problem << '\n';
            status = exit_bad_input;
        }
    }
    return status;
}

}  // namespace

int lesson_command(const LessonOptions& options, std::ostream& out, std::ostream& err) {
    const std::optional<std::filesystem::path> progress_path = course::progress_file();
    course::LoadedProgress loaded;
    if (progress_path) loaded = course::load_progress(*progress_path);
    if (!loaded.note.empty()) err << "impulse-lab: note: " << loaded.note << '\n';
    if (!options.number) return list_lessons(options, loaded.progress, out, err);
    if (options.text && (options.headless || options.script || options.screenshot || options.out || options.size))
        throw formats::InputError("--text", std::string("takes the lesson in the terminal; ") +
                                                (options.headless     ? "--headless"
                                                 : options.script     ? "--script"
                                                 : options.screenshot ? "--screenshot"
                                                 : options.out        ? "--out"
                                                                      : "--size") +
                                                " is for the window and its pictures");

    std::optional<std::filesystem::path> file;
    for (const std::filesystem::path& f : course::lesson_files(lessons_folder(options)))
        if (std::atoi(f.filename().string().c_str()) == *options.number) file = f;
    if (!file)
        throw formats::InputError("lesson", "there is no lesson " + std::to_string(*options.number) + " in " +
                                                lessons_folder(options).string() + " (impulse-lab lesson lists them)");
    course::PreparedLesson prepared = course::prepare_lesson(course::read_lesson(*file));
    for (const std::string& note : prepared.lesson.notes) err << "note: " << file->string() << ": " << note << '\n';

    const bool window = !options.text && !options.headless && gui::display_available();
    gui::InspectorRun run;
    if (options.size) std::tie(run.width, run.height) = parse_window_size(*options.size);
    run.lesson = &prepared;
    run.progress = &loaded.progress;
    run.progress_file = progress_path;
    run.headless = !window;
    if (window) {
        if (options.script) {
            run.script_name = *options.script;
            run.script = read_script_file(*options.script);
        }
        run.screenshot = options.screenshot;
        // A picture on standard output, as inspect's (cli/outputs.hpp): what the lesson says goes to stderr then.
        if (options.screenshot && names_standard_output(*options.screenshot, out)) {
            if (is_terminal(out))
                throw formats::InputError("--screenshot",
                                          "standard output is a terminal; redirect it to a file or a pipe");
            run.standard_output = &out;
            return gui::run_inspector(prepared.session, run, err, err);
        }
        return gui::run_inspector(prepared.session, run, out, err);
    }
    if (options.script || options.screenshot)
        throw formats::InputError(options.script ? "--script" : "--screenshot",
                                  "is for the lesson's window; headless, every step is written as a PNG to --out");

    // A terminal to read from: the lesson asks and waits, and saves progress as the window does.
    if (options.terminal && !options.headless) {
        if (!options.text)
            err << "impulse-lab: note: no display (DISPLAY is not set): the lesson runs in this terminal "
                   "(--headless prints it with its answers and pictures)\n";
        course::LessonRun taking(prepared, progress_path ? &loaded.progress : nullptr, progress_path);
        course::take_lesson(taking, *options.terminal, out, terminal_width());
        return 0;
    }
    // Nothing to read answers from: the lesson with its answers, at once, never waiting.
    if (options.text) {
        course::write_annotated_lesson(out, prepared);
        return 0;
    }
    if (!options.headless)
        err << "impulse-lab: note: no display (DISPLAY is not set): the lesson is shown as text, with its "
               "pictures in a folder\n";
    char default_folder[32];
    std::snprintf(default_folder, sizeof default_folder, "lesson-%02d", prepared.lesson.number);
    const std::filesystem::path folder = options.out ? std::filesystem::path(*options.out) : default_folder;
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) throw formats::InputError("--out", "cannot create " + folder.string() + ": " + error.message());

    course::write_annotated_lesson(out, prepared);
    run.script_name = "lesson";
    for (std::size_t i = 0; i < prepared.places.size(); ++i) {
        char name[96];
        std::snprintf(name, sizeof name, "step-%02zu-%s.png", i + 1, prepared.lesson.steps[i].id.c_str());
        run.script.push_back({model::ActionKind::lesson_step, std::to_string(i + 1), 1, 0});
        run.script.push_back({model::ActionKind::screenshot, (folder / name).string(), 1, 0});
    }
    run.script.push_back({model::ActionKind::export_trace, (folder / "trace.json").string(), 1, 0});
    // Text mode shows the answers, so it does not move the student's saved place or record answers; its
    // pictures show each step as a student who answered every question before it.
    run.progress = nullptr;
    run.lesson_preview = true;
    const int status = gui::run_inspector(prepared.session, run, out, err);
    if (status == 0)
        out << "\nWrote " << prepared.places.size() << " screenshots and trace.json to " << folder.string() << '\n';
    return status;
}

}  // namespace impulse::cli
