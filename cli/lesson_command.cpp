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
#include "formats/settings_json.hpp"
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
            err << error_line(e);
            status = exit_bad_input;
        }
    }
    return status;
}

}  // namespace

namespace {

// The lesson numbered `number` in the lessons folder, prepared with the --set settings after its own.
course::PreparedLesson prepared_lesson(const LessonOptions& options, int number, std::ostream& err) {
    std::optional<std::filesystem::path> file;
    for (const std::filesystem::path& f : course::lesson_files(lessons_folder(options)))
        if (std::atoi(f.filename().string().c_str()) == number) file = f;
    if (!file)
        throw formats::InputError("lesson", "there is no lesson " + std::to_string(number) + " in " +
                                                lessons_folder(options).string() + " (impulse-lab lesson lists them)");
    course::Lesson lesson = course::read_lesson(*file);
    for (const std::string& s : options.settings) lesson.settings.push_back(s);
    course::PreparedLesson prepared = course::prepare_lesson(std::move(lesson));
    for (const std::string& note : prepared.lesson.notes) err << "note: " << file->string() << ": " << note << '\n';
    return prepared;
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
    // A setting is checked before the lesson runs, so its error names the flag.
    for (const std::string& s : options.settings) {
        Scene probe;
        formats::apply_setting(probe, s, "--set");
    }
    // With other settings the answers are that run's: they are not the course's, so they are not kept.
    const bool keep_progress = progress_path && options.settings.empty();
    if (!options.settings.empty())
        err << "impulse-lab: note: --set: the lesson runs with other settings and its questions are graded "
               "against that run; your progress is not saved\n";

    course::PreparedLesson prepared = prepared_lesson(options, *options.number, err);
    const std::filesystem::path folder = lessons_folder(options);

    // A window, on the screen or (a script's keys driving it) offscreen.
    const bool window = !options.text && (options.script ? true : !options.headless && gui::display_available());
    if (window) {
        gui::InspectorRun run;
        if (options.size) std::tie(run.width, run.height) = parse_window_size(*options.size);
        run.fit_to_screen = !options.size;
        run.headless = options.headless || !gui::display_available();
        run.progress = keep_progress ? &loaded.progress : nullptr;
        run.progress_file = keep_progress ? progress_path : std::nullopt;
        if (options.script) {
            run.script_name = *options.script;
            run.script = read_script_file(*options.script);
        }
        run.screenshot = options.screenshot;
        bool open_next = false;
        run.next_lesson_chosen = &open_next;
        // A picture on standard output, as inspect's (cli/outputs.hpp): what the lesson says goes to stderr then.
        std::ostream* said = &out;
        if (options.screenshot && names_standard_output(*options.screenshot, out)) {
            if (is_terminal(out))
                throw formats::InputError("--screenshot",
                                          "standard output is a terminal; redirect it to a file or a pipe");
            run.standard_output = &out;
            said = &err;
        }
        // The end of a lesson offers the next one: it opens in a new window, without the script.
        for (int status = 0;;) {
            run.lesson = &prepared;
            run.next_lesson = course::lesson_after(folder, prepared.lesson.number);
            open_next = false;
            status = gui::run_inspector(prepared.session, run, *said, err);
            if (status != 0 || !open_next || !run.next_lesson) return status;
            prepared = prepared_lesson(options, run.next_lesson->number, err);
            run.script.clear();
            run.screenshot.reset();
        }
    }
    if (options.screenshot)
        throw formats::InputError("--screenshot",
                                  "is for the lesson's window; headless, every step is written as a PNG to --out");

    // A terminal to read from: the lesson asks and waits, and saves progress as the window does.
    if (options.terminal && !options.headless) {
        if (!options.text)
            err << "impulse-lab: note: no display (DISPLAY is not set): the lesson runs in this terminal "
                   "(--headless prints it with its answers and pictures)\n";
        while (true) {
            course::LessonRun taking(prepared, keep_progress ? &loaded.progress : nullptr,
                                     keep_progress ? progress_path : std::nullopt);
            const std::optional<course::LessonLink> next = course::lesson_after(folder, prepared.lesson.number);
            const course::TerminalOutcome outcome =
                course::take_lesson(prepared, taking, *options.terminal, out, terminal_width(), next);
            if (!outcome.next_lesson || !next) return 0;
            prepared = prepared_lesson(options, next->number, err);
        }
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
    const std::filesystem::path pictures = options.out ? std::filesystem::path(*options.out) : default_folder;
    std::error_code error;
    std::filesystem::create_directories(pictures, error);
    if (error) throw formats::InputError("--out", "cannot create " + pictures.string() + ": " + error.message());

    course::write_annotated_lesson(out, prepared);
    gui::InspectorRun run;
    if (options.size) std::tie(run.width, run.height) = parse_window_size(*options.size);
    run.lesson = &prepared;
    run.headless = true;
    run.script_name = "lesson";
    for (std::size_t i = 0; i < prepared.places.size(); ++i) {
        char name[96];
        std::snprintf(name, sizeof name, "step-%02zu-%s.png", i + 1, prepared.lesson.steps[i].id.c_str());
        run.script.push_back({model::ActionKind::lesson_step, std::to_string(i + 1), 1, 0});
        run.script.push_back({model::ActionKind::screenshot, (pictures / name).string(), 1, 0});
    }
    run.script.push_back({model::ActionKind::export_trace, (pictures / "trace.json").string(), 1, 0});
    // Text mode shows the answers, so it does not move the student's saved place or record answers; its
    // pictures show each step as a student who answered every question before it.
    run.lesson_preview = true;
    const int status = gui::run_inspector(prepared.session, run, out, err);
    if (status == 0)
        out << "\nWrote " << prepared.places.size() << " screenshots and trace.json to " << pictures.string() << '\n';
    return status;
}

}  // namespace impulse::cli
