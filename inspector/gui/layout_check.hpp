#pragma once
// The lesson window's layout, checked from ImGui's own item rectangles: every step of a lesson laid out at
// a window size, as the student meets it (the questions before it answered), and for a question also after
// a wrong answer, after the right one and after a skip; every text and control of the lesson panel must lie
// inside the window, and a question's options, its Check and Skip buttons and its verdict must be there.
// ImGui lays the frames out in its own context with the inspector's fonts; nothing is rasterised, so a whole
// course takes seconds.

#include "lessons/lesson.hpp"

#include <string>
#include <vector>

namespace impulse::gui {

struct LayoutReport {
    int states = 0;                     // step states laid out
    int items = 0;                      // items checked
    std::vector<std::string> problems;  // one line each: "step 3 (answered wrong): button Check at ... outside ..."
};

// Throws DisplayError when ImGui cannot be set up.
LayoutReport check_lesson_layout(lessons::PreparedLesson& lesson, int width, int height);

}  // namespace impulse::gui
