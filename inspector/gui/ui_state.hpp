#pragma once
// What the window remembers between frames: the view of the scene, the export paths, the last message,
// and the values rebuilt from the trace whenever the cursor or the trace changes (never every frame: a
// fully recorded frame of the 1000-box grid has 4000 contacts).

#include "course/lesson.hpp"
#include "course/progress.hpp"
#include "model/derivation_view.hpp"
#include "model/replay.hpp"
#include "model/script.hpp"
#include "model/session.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

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
    std::optional<inspect::Cursor> cursor;
    inspect::DerivationView derivation;
    std::vector<inspect::ContactRow> contacts;
    inspect::BodiesAtCursor bodies;
    std::vector<explain::StepTable> steps;  // of the cursor's item, for the navigator's step list
    // Per frame: the phase curves and the largest impulse, which scales the impulse arrows.
    int frame = -1;
    std::vector<inspect::PhaseCurve> curves;
    double largest_impulse = 0.0;
    bool scroll_to_cursor = false;  // the panels bring the cursor's rows into view once after a move
};

// A lesson open in the window: which step the student is on, what they typed, what they were told.
struct LessonState {
    lessons::PreparedLesson* lesson = nullptr;  // owned by the lesson command
    int step = 0;
    std::array<char, 64> typed{};
    std::vector<std::optional<lessons::Verdict>> verdicts;  // per step; set once answered
    lessons::Progress* progress = nullptr;                  // saved after every answer and move, when given
    std::optional<std::filesystem::path> progress_file;
};

struct UiState {
    SceneCamera camera;
    std::optional<LessonState> lesson;
    CursorViews views;
    std::array<char, 512> trace_path{"trace.json"};
    std::array<char, 512> table_path{"table.csv"};
    std::array<char, 512> screenshot_path{"screenshot.png"};
    std::vector<int> pressed_keys;  // SDL scancodes pressed since the last frame, for the navigation keys
    std::string message;            // the last export's or setting's outcome, shown in the status line
    bool message_is_error = false;
};

// Rebuilds `state.views` if the session's trace or cursor changed since the last call.
void refresh_views(const inspect::Session& session, UiState& state);

// Goes to step `step` of the open lesson: its place in the trace, and the step's text and question.
void go_to_lesson_step(inspect::Session& session, UiState& state, int step);

// The quantity whose values are hidden: the current lesson step's question's, until it is answered.
// Empty when nothing is hidden.
std::string hidden_quantity(const UiState& state, const inspect::Session& session);
// Whether a table row shows the hidden value: `question_path` is the question's full value path.
bool is_hidden_row(const std::string& hidden, const std::string& question_path, std::string_view quantity);

// Carries out an action from a key or a button; an error becomes the status message instead of an exit.
void act(inspect::Session& session, UiState& state, const inspect::Action& action, inspect::ActionHost& host);

}  // namespace impulse::gui
