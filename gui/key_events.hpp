#pragma once
// Keys and text as SDL events, put on SDL's own event queue: a script's `key` and `type` lines (and the tests that
// take whole lessons) reach the window exactly as a keyboard's do, through the same queue and the same handlers.

#include <string>

namespace impulse::gui {

// A key chord: an SDL key name ("Right", "Return", "Tab", "Escape", "Page Down", "S") with "ctrl+", "shift+" or
// "alt+" before it, pressed and released. Throws formats::InputError("key", ...) for a name SDL does not know.
void push_key(const std::string& chord);

// Text as typed: SDL_TEXTINPUT events (UTF-8, a few characters each).
void push_text(const std::string& text);

}  // namespace impulse::gui
