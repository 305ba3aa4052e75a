#pragma once
// The course's front page, as the site opens on it: the fourteen lessons with how far the student got in each, the
// shipped scenes and cases to open in the inspector, the student's own files, and their progress to take away or
// bring back. What a button does is the platform's (the page's file picker, a download): it comes as actions.

#include "course/progress.hpp"
#include "gui/ui_state.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace impulse::gui {

struct CourseListing {
    struct LessonLine {
        int number = 0;
        std::string title;
        int steps = 0;
        int questions = 0;
        std::string progress;  // "not started", or the tally: "3 right at the first try, 1 skipped"
    };
    std::vector<LessonLine> lessons;
    std::vector<std::filesystem::path> scenes;  // the shipped scenes, then
    std::vector<std::filesystem::path> cases;   // the shipped cases
    std::vector<std::string> problems;          // a lesson file that could not be read, one line each
};

// The lessons of `data/lessons` and the scenes and cases of `data/scenes`, with the student's progress.
CourseListing list_course(const std::filesystem::path& data, const course::Progress& progress);

struct StartPageActions {
    std::function<void(int number)> open_lesson;
    std::function<void(const std::filesystem::path& file)> open_file;
    std::function<void()> pick_file;        // the student's own scene, case or trace
    std::function<void()> export_progress;  // progress.json, as the desktop writes it
    std::function<void()> import_progress;
    // The lesson's worksheet (as `impulse-lab worksheet LESSON --out sheet.csv` writes it), for a teacher to hand out.
    std::function<void(int number)> worksheet;
};

// The page, filling the window. `message` is the last outcome (an error in red). `controls`, when given, gets the
// buttons as laid out ("button Open 3", "button Worksheet 3", "button Export progress.json"), for a browser test.
void draw_start_page(const CourseListing& listing, const std::string& message, bool message_is_error,
                     const StartPageActions& actions, std::vector<LaidOutItem>* controls = nullptr);

}  // namespace impulse::gui
