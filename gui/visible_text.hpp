#pragma once
// The text a frame shows, read back from what ImGui drew: every glyph quad of the draw data, matched to its
// glyph in the font atlas, kept when it lies inside its clip rectangle, and joined into runs of text (a word
// group, a table cell) per window and line. Tests read it to check that nothing on screen gives an answer away,
// whichever panel, tooltip or label drew it.

#include <string>
#include <vector>

struct ImDrawData;

namespace impulse::gui {

struct VisibleRun {
    std::string window;  // the ImGui window that drew it ("Derivation", "##tabs", "Lesson", ...)
    std::string text;    // UTF-8, spaces where the glyphs leave a gap
    float x = 0, y = 0;  // where it starts on the screen
};

// The runs of the current ImGui context's last rendered frame (ImGui::GetDrawData()), top to bottom, left to
// right within each window.
std::vector<VisibleRun> visible_text(const ImDrawData& drawn);

}  // namespace impulse::gui
