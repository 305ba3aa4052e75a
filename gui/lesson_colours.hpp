#pragma once
// The lesson panel's colours, one meaning each: a title, a heading, a question, and a question's state (right,
// wrong, skipped, open), the same in the step list, the verdict and the end of the lesson.

#include <imgui.h>

namespace impulse::gui {

inline const ImVec4 title_colour(1.0f, 0.9f, 0.4f, 1.0f);
inline const ImVec4 heading_colour(0.75f, 0.95f, 0.55f, 1.0f);
inline const ImVec4 question_colour(0.6f, 0.85f, 1.0f, 1.0f);
inline const ImVec4 right_colour(0.5f, 0.9f, 0.5f, 1.0f);
inline const ImVec4 wrong_colour(1.0f, 0.65f, 0.4f, 1.0f);
inline const ImVec4 skipped_colour(0.75f, 0.75f, 1.0f, 1.0f);
inline const ImVec4 open_colour(1.0f, 0.72f, 0.3f, 1.0f);
inline const ImVec4 error_colour(1.0f, 0.45f, 0.4f, 1.0f);

}  // namespace impulse::gui
