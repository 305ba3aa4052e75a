#pragma once
// The keys the panels read, by the USB HID usage number of the key: the numbers SDL's scancodes are (display_sdl.cpp
// checks that they agree) and those the browser's display gives a KeyboardEvent's code (web/display_web.cpp). So
// the panels read the same keys on every platform, with no window system's header.

namespace impulse::gui::key {

inline constexpr int a = 4, c = 6, s = 22, v = 25, x = 27, y = 28, z = 29;
inline constexpr int enter = 40, escape = 41, backspace = 42, tab = 43, space = 44;
inline constexpr int insert = 73, home = 74, page_up = 75, del = 76, end = 77, page_down = 78;
inline constexpr int right = 79, left = 80, down = 81, up = 82;
inline constexpr int keypad_enter = 88;
inline constexpr int left_ctrl = 224, left_shift = 225, left_alt = 226, left_gui = 227;
inline constexpr int right_ctrl = 228, right_shift = 229, right_alt = 230, right_gui = 231;

}  // namespace impulse::gui::key
