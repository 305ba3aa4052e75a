#pragma once
// The inspector's fonts: DejaVu Sans for text and DejaVu Sans Mono for values, with the Greek letters,
// arrows, sub- and superscripts and mathematical operators the tables use (Δ, ε, ×, →, ᵀ, ...).

#include <string>

struct ImGuiIO;
struct ImFont;

namespace impulse::gui {

// Loads the fonts into `io`, rasterised at `pixel_ratio` times their size and drawn scaled back by as much (sharp on
// a high-density screen, the same layout). Returns a one-line note when they are missing (ImGui's built-in font is
// then used, which shows those symbols as '?'), else an empty string.
std::string load_fonts(ImGuiIO& io, float pixel_ratio = 1.0f);

// The monospaced font for values: the second font loaded, or the default font when it is missing.
ImFont* value_font();

}  // namespace impulse::gui
