#pragma once
// Text wrapped to a width without breaking numbers: ImGui's own wrapping breaks after a full stop, so
// "0.0124663" could become "0." and "0124663" on two lines, and it cuts any word too long for the line.
// Here lines break at spaces only; a word wider than the line is split between characters unless it holds
// a digit (a number, a vector's component, a value with its exponent), which is kept whole.

#include <string>
#include <string_view>
#include <vector>

namespace impulse::gui {

// The lines `text` takes at `width` pixels in the current font (its own line breaks kept).
std::vector<std::string> wrap_lines(std::string_view text, float width);
// Their height in pixels, drawn as one text item.
float wrapped_height(std::string_view text, float width);
// Draws them as one text item (so one rectangle holds them). `width` <= 0: the space left on the line.
void wrapped_text(std::string_view text, float width = 0.0f);
// The widest word of `text` that is never split (one holding a digit), in pixels: a column narrower than
// this would cut a number.
float widest_unbreakable(std::string_view text);
// The widest word of `text`, in pixels: a column at least this wide splits no word.
float widest_word(std::string_view text);

}  // namespace impulse::gui
