#pragma once
// The site: the start page, a lesson or a file in the inspector, one at a time, in the page's canvas. The page's
// address says which (index.html#lesson=3 opens lesson 3; no fragment, the start page), so a teacher can link a
// lesson and the browser's Back returns to the start page. Every frame the page asks for is one frame of the same
// InspectorApp the desktop runs; the student's progress is the desktop's progress.json, kept in the browser's
// storage after every change.

#include "course/lesson.hpp"
#include "course/progress.hpp"
#include "gui/display.hpp"
#include "gui/inspector_app.hpp"
#include "gui/start_page.hpp"
#include "model/session.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace impulse::web {

class Site {
public:
    Site();  // throws gui::DisplayError when the page gives no WebGL 2 context
    ~Site();

    // One frame, when the page asks for one; nothing is drawn while nothing changes.
    void frame();
    // The address's fragment changed (a link, Back): open what it names.
    void route(const std::string& fragment);
    // A file the student picked or dropped, written at `path`: a scene, case or trace to inspect, or progress.
    void file_picked(const std::string& path, bool as_progress);
    // The state a test reads (tests/web/browser.mjs): the page, the lesson and its question, the message, the
    // lesson panel's items as laid out, and the frame count.
    std::string test_state() const;
    // The app's own layout check for the open lesson at this window size: its problems, one per line.
    std::string layout_check(int width, int height);

private:
    struct Open;  // a lesson or a file, with its inspector
    void show_start(const std::string& message = {}, bool is_error = false);
    void open_lesson(int number);
    void open_file(const std::filesystem::path& file);
    std::optional<std::filesystem::path> lesson_file(int number) const;
    void download_worksheet(int number);
    void save_if_changed();

    std::optional<gui::Display> display_;
    std::optional<std::filesystem::path> progress_file_;
    course::Progress progress_;
    gui::CourseListing listing_;
    gui::StartPageActions actions_;
    std::vector<gui::LaidOutItem> start_controls_;  // the start page's buttons as laid out, for the test hook
    std::unique_ptr<Open> open_;
    std::function<void()> pending_;  // what a start page button asked for, done after its frame
    std::string message_;
    bool message_is_error_ = false;
    std::ostringstream errors_;  // what the inspector would print on a terminal
    long long frames_ = 0;
    int settle_ = 3;           // frames to draw before idling
    std::string saved_stamp_;  // the progress file's identity when last stored
};

}  // namespace impulse::web
