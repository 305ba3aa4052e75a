#pragma once
// The text a frame shows, read back from what ImGui drew: every glyph quad of the draw data, matched to its
// glyph in the font atlas, kept when it lies inside its clip rectangle, and joined into runs of text (a word
// group, a table cell) per window and line. Tests read it to check that nothing on screen gives an answer away,
// whichever panel, tooltip or label drew it.

#include <memory>
#include <string>
#include <vector>

struct ImDrawData;
struct ImFontAtlas;

namespace impulse::gui {

struct VisibleRun {
    std::string window;  // the ImGui window that drew it ("Derivation", "##tabs", "Lesson", ...)
    std::string text;    // UTF-8, spaces where the glyphs leave a gap
    float x = 0, y = 0;  // where it starts on the screen
};

class AtlasIndex;

// Reads frames drawn with one font atlas (indexed once: which glyph covers each of its texels).
class TextReader {
public:
    explicit TextReader(const ImFontAtlas& atlas);
    ~TextReader();
    // The runs of a rendered frame (ImGui::GetDrawData()), top to bottom, left to right within each window.
    std::vector<VisibleRun> read(const ImDrawData& drawn) const;

private:
    std::unique_ptr<AtlasIndex> index_;
};

}  // namespace impulse::gui
