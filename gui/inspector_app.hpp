#pragma once
// Runs the inspector on an open session: in a window until it is closed, or headless for a script, a
// screenshot or a frame-time benchmark. Scripts run one action per frame, so in a window they can be
// watched; a screenshot is taken after the panels have settled. The desktop loops over the frames
// (run_inspector); a browser draws one whenever the page asks for one (web/site.cpp): both drive InspectorApp.

#include "course/lesson.hpp"
#include "course/lesson_end.hpp"
#include "course/progress.hpp"
#include "model/script.hpp"
#include "model/session.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace impulse::gui {

struct InspectorRun {
    bool headless = false;
    int width = 1280;
    int height = 800;
    bool fit_to_screen = false;               // a window sized to the display (90 %) rather than width x height
    std::string script_name;                  // for errors: "steps.txt"
    std::vector<model::Action> script;        // run first, in order
    std::optional<std::string> screenshot;    // taken after the script; then the inspector closes
    std::ostream* standard_output = nullptr;  // where an output named "-" goes (cli/outputs.hpp)
    std::optional<int> bench_frames;          // then render this many frames, one step apart, and print times
    double load_seconds = 0.0;                // how long opening the file took, for the benchmark's report
    // A lesson shown beside the inspector (its session is the one inspected), and where progress is saved.
    course::PreparedLesson* lesson = nullptr;
    course::Progress* progress = nullptr;
    bool lesson_preview = false;  // each step pictured with the questions before it answered, none recorded
    std::optional<std::filesystem::path> progress_file;
    // The lesson offered at the lesson's end; set to true in `next_lesson_chosen` when the student opens it (the
    // window then closes, for the caller to open that lesson).
    std::optional<course::LessonLink> next_lesson;
    bool* next_lesson_chosen = nullptr;
    // Given every file an export or a screenshot wrote: a browser offers it as a download (web/); none on the
    // desktop, where the file is the user's already.
    std::function<void(const std::string& path)> offer_file;
};

class Display;
struct UiState;

// The inspector on one open session, one frame at a time.
class InspectorApp {
public:
    // `display` is open; the session, and the run's lesson and progress, outlive the app. Errors go to `err`.
    InspectorApp(model::Session& session, const InspectorRun& run, Display& display, std::ostream& err);
    ~InspectorApp();
    InspectorApp(const InspectorApp&) = delete;
    InspectorApp& operator=(const InspectorApp&) = delete;

    // One frame: the window's events, every panel, a screenshot when one is due, then the script's next action.
    // False once the inspector is done: the window closed, quit (Esc in a lesson), the script and screenshot done
    // headless, or a script's action failed (status() is then 2, and the reason is on `err`).
    bool frame();
    // Whether the next frame would change nothing unless an event comes: no action or screenshot waits and the
    // panels have settled.
    bool idle() const;
    int status() const;
    UiState& state();
    // Renders `frames` frames one derivation step apart and prints their times (--bench-frames).
    void bench(int frames, std::ostream& out);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Returns the exit code. Bad script actions and unwritable outputs are reported as one line on `err`
// (exit 2); a window that cannot be opened likewise.
int run_inspector(model::Session& session, const InspectorRun& run, std::ostream& out, std::ostream& err);

}  // namespace impulse::gui
