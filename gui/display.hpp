#pragma once
// The window the inspector draws in: an SDL2 window with an OpenGL 3.2 context and Dear ImGui on top.
// Headless, SDL's offscreen driver gives the same context through EGL and Mesa, so the same frames are
// rendered without a display and read back as pixels.

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

struct SDL_Window;
union SDL_Event;

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
// check, which lays the window out without one). Returns the fonts' note (empty when they were found).
std::string set_up_imgui();

// Whether a window could be shown here: false when neither DISPLAY nor WAYLAND_DISPLAY is set.
bool display_available();

struct Pixels {
    int width = 0;
    int height = 0;
    std::vector<unsigned char> rgba;  // top row first
};

struct GlCalls;

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
    // The keys pressed since the last frame (SDL scancodes, auto-repeat included), in order. ImGui 1.86 only
    // sees whether a key is down at each frame, so a press and release within one frame would be lost.
    const std::vector<int>& pressed_keys() const { return pressed_keys_; }
    // A note for the user about the fonts (empty when the fonts were found).
    const std::string& font_note() const { return font_note_; }

private:
    bool headless_;
    std::unique_ptr<GlCalls> gl_;
    SDL_Window* window_ = nullptr;
    void* gl_context_ = nullptr;
    bool imgui_ready_ = false;
    bool quit_ = false;
    bool had_events_ = false;
    std::vector<int> pressed_keys_;
    std::vector<SDL_Event> deferred_;  // key releases passed to ImGui a frame after their press
    struct Colour {
        float x, y, z, w;
    } window_background_{};
    std::string font_note_;
};

// The pixels as a PNG file's bytes.
std::string encode_png(const Pixels& pixels);

}  // namespace impulse::gui
