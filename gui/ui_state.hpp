#pragma once
// What the window remembers between frames: the view of the scene, the export paths, the last message, the
// panels' sizes, the open lesson, and the values rebuilt from the trace whenever the cursor or the trace
// changes (never every frame: a fully recorded frame of the 1000-box grid has 4000 contacts).

#include "course/lesson.hpp"
#include "course/lesson_end.hpp"
#include "course/lesson_run.hpp"
#include "course/mask.hpp"
#include "course/progress.hpp"
#include "model/derivation_view.hpp"
#include "model/replay.hpp"
#include "model/script.hpp"
#include "model/session.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

struct ImVec2;

namespace impulse::gui {

enum class ViewPlane { front, top, side, perspective };

struct SceneCamera {
    ViewPlane plane = ViewPlane::front;
    float yaw = 0.6f;     // radians about +y, for the rotatable view
    float pitch = 0.35f;  // radians about the view's x axis
    float zoom = 1.0f;    // on top of the fit to the bodies
    float pan_x = 0.0f;   // pixels
    float pan_y = 0.0f;
};

// Everything derived from (trace, cursor), rebuilt only when either changes.
struct CursorViews {
    int revision = -1;
    std::optional<model::Cursor> cursor;
    model::DerivationView derivation;
    std::vector<model::ContactRow> contacts;
    model::BodiesAtCursor bodies;
    std::vector<explain::StepTable> steps;  // of the cursor's item, for the navigator's step list
    // Per frame: the phase curves and the largest impulse, which scales the impulse arrows.
    int frame = -1;
    std::vector<model::PhaseCurve> curves;
    double largest_impulse = 0.0;
    bool scroll_to_cursor = false;  // the panels bring the cursor's rows into view once after a move
    // Rows of the derivation table hidden when it was last drawn, to bring the ones an answer reveals into view.
    std::vector<bool> hidden_rows;
    int hidden_rows_mask = -1;  // the mask_revision they were drawn with
    // The rows the derivation table brings into view, for a few frames (a table remade at new column widths
    // lays its rows out again), and the room left above them.
    std::vector<bool> bring_rows;
    int bring_frames = 0;
    float bring_context = 0.0f;
};

// A lesson open in the window: the student's run through it, what they are typing or have picked, and what
// its open questions hide.
struct LessonState {
    explicit LessonState(course::LessonRun taking, bool preview_only = false)
        : run(std::move(taking)), preview(preview_only) {}

    course::LessonRun run;
    std::array<char, 64> typed{};
    int chosen = -1;           // a choose question's option, from 0; -1 none
    bool focus_answer = true;  // give the answer field the keyboard at the next frame
    // Worked out on the session's trace; again when a setting re-runs it.
    std::vector<std::optional<course::QuestionReach>> reaches;
    int reaches_revision = -1;
    // The headless pictures of `lesson --headless`: each step shown with the questions before it answered.
    bool preview = false;
    // The lesson after this one, offered at its end (none after the last lesson).
    std::optional<course::LessonLink> next_lesson = {};
    // Why the last Enter did nothing ("type your answer first"), shown beside the answer field.
    std::string field_error = {};
    // A move away from a step whose question is still open waits for the student's word: where it goes (the
    // step count: the end of the lesson). The panel asks "skip this question?" meanwhile.
    std::optional<int> leaving = {};
    bool caret_to_end = false;              // typed text reached the field before it had the keyboard: no select-all
    bool field_active = false;              // the answer field had the keyboard at the end of the last frame
    bool focus_pending = false;             // the keyboard was asked for the field last frame: it takes it now
    bool finished = false;                  // the end-of-lesson screen is shown
    bool open_next = false;                 // the student asked for the next lesson: the window closes to open it
    std::optional<int> go_to_request = {};  // a step a panel's link asked for, taken up by the lesson panel
};

// The panels' sizes, as the user dragged the splitters (0: the default for the window's size).
struct PanelSizes {
    float lesson_width = 0.0f;      // a lesson's panel, pixels
    float left_width = 0.0f;        // the inspector's navigator and settings column, pixels
    float right_width = 0.0f;       // its contacts, bodies and plots column, pixels
    float derivation_share = 0.0f;  // of the height below the toolbar, above the scene
    float scene_share = 0.0f;       // with a lesson: of the width beside the lesson, left of the tabs
};

// One item of the lesson panel as ImGui laid it out, for the layout test.
struct LaidOutItem {
    std::string what;  // "text", "button Check", "option 2", "input", ...
    float min_x, min_y, max_x, max_y;
    // The visible region it was drawn in (the panel, or the scrolling text inside it), and whether that
    // region scrolls vertically (text below its bottom is then reached by scrolling).
    float region_min_x, region_min_y, region_max_x, region_max_y;
    bool scrolls;
};

struct UiState {
    SceneCamera camera;
    PanelSizes sizes;
    std::optional<LessonState> lesson;
    course::Mask mask;      // what the lesson's open questions hide (nothing without a lesson)
    int mask_revision = 0;  // counts the mask's changes: an answer or a skip reveals rows to bring into view
    CursorViews views;
    std::array<char, 512> trace_path{"trace.json"};
    std::array<char, 512> table_path{"table.csv"};
    std::array<char, 512> screenshot_path{"screenshot.png"};
    std::vector<int> pressed_keys;  // SDL scancodes pressed since the last frame, for the keys
    std::string message;            // the last export's or setting's outcome, shown in the status line
    bool message_is_error = false;
    bool quit = false;  // Esc in a lesson: the window closes
    // A tab of the lesson's panel to bring to the front at the next frame ("Bodies"), then cleared: how a test
    // looks at every panel.
    std::string show_tab;
    // Filled by the lesson panel every frame while `record_layout` is set.
    bool record_layout = false;
    std::vector<LaidOutItem> layout;
    // The inspector's tabs and export buttons as laid out, while `record_layout` is set: where a browser test
    // clicks (web/site.cpp's test hook). Not the lesson panel's, so the layout check does not hold them to it.
    std::vector<LaidOutItem> controls;
    float lesson_panel[4] = {0, 0, 0, 0};  // the lesson window's rectangle: min x, min y, max x, max y
};

// Rebuilds `state.views` (and the lesson's mask) if the session's trace or cursor changed since the last call.
void refresh_views(const model::Session& session, UiState& state);
// Works out the mask again: after an answer or a skip, and when the trace changed.
void refresh_mask(const model::Session& session, UiState& state);

// Goes to step `step` of the open lesson: its place in the trace, and the step's text and question.
void go_to_lesson_step(model::Session& session, UiState& state, int step);

// Carries out an action from a key or a button; an error becomes the status message instead of an exit.
void act(model::Session& session, UiState& state, const model::Action& action, model::ActionHost& host);

// Records the last ImGui item (its rectangle and the window it shows in) while the layout is recorded.
// `scrolls`: that window scrolls vertically, so the item may lie below its bottom until scrolled to.
void record_item(UiState& state, const char* what, bool scrolls = false);
// The last item as one of `controls` (while `record_layout` is set), and `controls` it is added to.
void record_control(std::vector<LaidOutItem>& controls, const std::string& what);
void record_control(UiState& state, const std::string& what);

}  // namespace impulse::gui
