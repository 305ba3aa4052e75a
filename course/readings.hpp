#pragma once
// A lesson's text read in the window or in the terminal. Where the two differ — the window has panels and tabs,
// the terminal has keys — the text holds both readings, `{{the bodies panel|the bodies (key o)}}`: the window's
// before the bar, the terminal's after it. One text per lesson, so the two never drift apart.

#include <string>
#include <string_view>

namespace impulse::course {

enum class Reading { window, terminal };

// `text` with each {{window|terminal}} pair replaced by the reading asked for.
std::string reading(std::string_view text, Reading which);

// Throws formats::InputError(where, ...) for a {{ without its }} or without a |, or a }} without its {{.
void check_readings(std::string_view text, const std::string& where);

}  // namespace impulse::course
