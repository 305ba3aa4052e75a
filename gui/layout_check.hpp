#pragma once
// The lesson window's layout, checked from ImGui's own item rectangles: every step of a lesson laid out at
// a window size, as the student meets it (the questions before it answered), and for a question also after
// a wrong answer, while it asks before leaving the question open, and after a skip, then the end of the lesson;
// every text and control of the lesson panel must lie
// inside the window, and a question's options, its Check and Skip buttons and its verdict must be there.
// ImGui lays the frames out in its own context with the inspector's fonts; nothing is rasterised, so a whole
// course takes seconds.

#include "gui/ui_state.hpp"
#include "course/lesson.hpp"

#include <string>
#include <vector>

struct ImGuiContext;

namespace impulse::gui {

struct LayoutReport {
    int states = 0;                     // step states laid out
    int items = 0;                      // items checked
    std::vector<std::string> problems;  // one line each: "step 3 (answered wrong): button Check at ... outside ..."
};

LayoutReport check_lesson_layout(course::PreparedLesson& lesson, int width, int height);

// The inspector's window laid out frame by frame in its own ImGui context (the inspector's fonts and
// style, nothing rasterised), with the mouse where a test puts it: how the layout check and the tests drive
// the panels without a display.
class OffscreenLayout {
public:
    OffscreenLayout(int width, int height);
    ~OffscreenLayout();
    OffscreenLayout(const OffscreenLayout&) = delete;
    OffscreenLayout& operator=(const OffscreenLayout&) = delete;

    // One frame of the whole window, the mouse at (x, y) with its left button down or up.
    void frame(model::Session& session, UiState& state, float mouse_x = -1.0f, float mouse_y = -1.0f,
               bool mouse_down = false);

private:
    ImGuiContext* previous_;
    ImGuiContext* context_;
};

}  // namespace impulse::gui
