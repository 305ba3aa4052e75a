#pragma once
// The window the inspector draws in: an OpenGL ES 3 / OpenGL 3.2 context with Dear ImGui on top, and the keys,
// mouse and size of whatever shows it. That part is the platform's (docs/design.md, "The browser"): on the
// desktop an SDL2 window (display_sdl.cpp), headless SDL's offscreen driver through EGL and Mesa, so the same
// frames are rendered without a display and read back as pixels; in a browser the page's canvas with WebGL 2
// (web/display_web.cpp). Everything drawn in it is the same code.

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace impulse::gui {

// Why the window could not be opened, as one line.
class DisplayError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct DisplayOptions {
    bool headless = false;
    int width = 1280;
    int height = 800;
    // A window (not headless) sized to the display instead: 90 % of its usable area, never larger.
    bool fit_to_screen = false;
    std::string title = "Impulse Lab";
};

// The fonts and style of the inspector, in the current ImGui context (Display does this; so does the layout
// check, which lays the window out without one). `pixel_ratio` is the screen's pixels per layout pixel (2 on a
// high-density display): the fonts are rasterised at that many times their size and drawn scaled back, so text
// is sharp and the layout is the same. Returns the fonts' note (empty when they were found).
std::string set_up_imgui(float pixel_ratio = 1.0f);

// Whether a window could be shown here: false when neither DISPLAY nor WAYLAND_DISPLAY is set.
bool display_available();

struct Pixels {
    int width = 0;
    int height = 0;
    std::vector<unsigned char> rgba;  // top row first
};

class Display {
public:
    explicit Display(const DisplayOptions& options);  // throws DisplayError
    ~Display();
    Display(const Display&) = delete;
    Display& operator=(const Display&) = delete;

    // Handles window events and starts an ImGui frame; false once the user closed the window. `idle`: nothing
    // is animating, so a window sleeps until an event comes (or a quarter second passes) instead of spinning.
    bool begin_frame(bool idle = false);
    // Renders the frame. `capture` reads the finished frame back before it is shown.
    void end_frame(Pixels* capture = nullptr);

    bool headless() const { return headless_; }
    // Whether the last begin_frame handled any input or window event.
    bool had_events() const { return had_events_; }
    // Whether input or a change of size waits to be handled (a browser draws a frame only then, or while busy).
    bool events_waiting() const;
    // The keys pressed since the last frame (SDL scancodes, which are USB HID usage numbers, so a browser's keys
    // map to the same; auto-repeat included), in order. ImGui 1.86 only sees whether a key is down at each frame,
    // so a press and release within one frame would be lost.
    const std::vector<int>& pressed_keys() const { return pressed_keys_; }
    // A note for the user about the fonts (empty when the fonts were found).
    const std::string& font_note() const { return font_note_; }

    struct Platform;  // the window system's part: display_sdl.cpp, web/display_web.cpp

private:
    std::unique_ptr<Platform> platform_;
    bool headless_;
    bool had_events_ = false;
    std::vector<int> pressed_keys_;
    std::string font_note_;
};

// The pixels as a PNG file's bytes.
std::string encode_png(const Pixels& pixels);

}  // namespace impulse::gui
