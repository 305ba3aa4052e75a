// The inspector's window in a browser: the page's canvas with a WebGL 2 context (OpenGL ES 3, which ImGui's OpenGL3
// backend draws with as it does on the desktop), and the page's keys, mouse, wheel and size, through emscripten's
// html5 API. This is all a browser changes of the window (gui/display.hpp); the desktop's is gui/display_sdl.cpp.
//
// Keys become SDL scancodes, which are the USB HID usage numbers of the keys: the panels and ImGui's key map read
// the same numbers on both platforms. The canvas is sized in layout pixels by the page's CSS (the whole window)
// and its drawing buffer in the screen's pixels, so text is as sharp as the screen allows.

#include "gui/display.hpp"

#include "gui/fonts.hpp"
#include "gui/key_events.hpp"
#include "gui/keys.hpp"
#include "formats/input_error.hpp"

#include <GLES3/gl3.h>
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace impulse::gui {

namespace {

constexpr const char* canvas = "#canvas";

// KeyboardEvent.code to the key's USB HID usage (= SDL scancode), for the keys the inspector, its lessons and
// ImGui's text fields use; 0 for the rest.
int scancode(std::string_view code) {
    if (code.size() == 4 && code.starts_with("Key") && code[3] >= 'A' && code[3] <= 'Z') return 4 + (code[3] - 'A');
    if (code.size() == 6 && code.starts_with("Digit") && code[5] >= '0' && code[5] <= '9')
        return code[5] == '0' ? 39 : 30 + (code[5] - '1');
    if (code.size() == 7 && code.starts_with("Numpad") && code[6] >= '0' && code[6] <= '9')
        return code[6] == '0' ? 98 : 89 + (code[6] - '1');
    struct Named {
        std::string_view code;
        int usage;
    };
    constexpr Named named[] = {
        {"Enter", 40},       {"Escape", 41},        {"Backspace", 42},      {"Tab", 43},           {"Space", 44},
        {"Minus", 45},       {"Equal", 46},         {"Period", 55},         {"Slash", 56},         {"Comma", 54},
        {"Insert", 73},      {"Home", 74},          {"PageUp", 75},         {"Delete", 76},        {"End", 77},
        {"PageDown", 78},    {"ArrowRight", 79},    {"ArrowLeft", 80},      {"ArrowDown", 81},     {"ArrowUp", 82},
        {"NumpadEnter", 88}, {"NumpadDecimal", 99}, {"NumpadSubtract", 86}, {"NumpadAdd", 87},     {"ControlLeft", 224},
        {"ShiftLeft", 225},  {"AltLeft", 226},      {"MetaLeft", 227},      {"ControlRight", 228}, {"ShiftRight", 229},
        {"AltRight", 230},   {"MetaRight", 231},
    };
    for (const Named& n : named)
        if (code == n.code) return n.usage;
    return 0;
}

// What the page told us since the last frame, in order.
struct Event {
    enum class Kind { key_down, key_up, text, mouse_down, mouse_up, mouse_move, wheel, leave, blur };
    Event(Kind k, int c = 0, float at_x = 0.0f, float at_y = 0.0f, std::string typed = {})
        : kind(k), code(c), x(at_x), y(at_y), text(std::move(typed)) {}
    Kind kind;
    int code;  // scancode, or mouse button
    float x, y;
    std::string text;
};

// The display whose queue a script's keys go to: a page has one canvas.
Display::Platform* live_platform = nullptr;

EM_JS(void, set_canvas_cursor, (const char* cursor), {
    const element = document.querySelector('#canvas');
    if (element) element.style.cursor = UTF8ToString(cursor);
});

}  // namespace

struct Display::Platform {
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = 0;
    bool imgui_ready = false;
    std::vector<Event> events;
    float pixel_ratio = 1.0f;  // the fonts were rasterised for this one
    double last_time = 0.0;
    int buffer_width = 0, buffer_height = 0;
    ImVec4 background{};
    ImGuiMouseCursor cursor = ImGuiMouseCursor_Arrow;

    bool resized() const {
        double width = 0.0, height = 0.0;
        emscripten_get_element_css_size(canvas, &width, &height);
        const double ratio = emscripten_get_device_pixel_ratio();
        return std::lround(width * ratio) != buffer_width || std::lround(height * ratio) != buffer_height;
    }
};

namespace {

EM_BOOL on_key(int type, const EmscriptenKeyboardEvent* e, void* data) {
    auto& events = static_cast<Display::Platform*>(data)->events;
    const int code = scancode(e->code);
    const bool down = type == EMSCRIPTEN_EVENT_KEYDOWN;
    if (code != 0) events.push_back({down ? Event::Kind::key_down : Event::Kind::key_up, code});
    // A key that types one character types it (the answer field, a setting, an export's name).
    const bool command = e->ctrlKey || e->metaKey;
    if (down && !command && std::strlen(e->key) > 0 && std::strlen(e->key) <= 4) {
        const auto lead = static_cast<unsigned char>(e->key[0]);
        const std::size_t length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
        if (std::strlen(e->key) == length && lead >= 0x20) events.push_back({Event::Kind::text, 0, 0, 0, e->key});
    }
    // The page keeps the browser's own shortcuts (Ctrl or Cmd with a key, F5, F12) but Ctrl+S, which skips a
    // lesson's question (a page has nothing of its own to save); every other key is the inspector's, so Tab does
    // not leave the canvas and the arrows do not scroll the page.
    const bool function_key = e->code[0] == 'F' && e->code[1] >= '1' && e->code[1] <= '9';
    return (!command || (e->ctrlKey && code == key::s)) && !function_key;
}

EM_BOOL on_mouse(int type, const EmscriptenMouseEvent* e, void* data) {
    auto& events = static_cast<Display::Platform*>(data)->events;
    const auto x = static_cast<float>(e->targetX), y = static_cast<float>(e->targetY);
    switch (type) {
        case EMSCRIPTEN_EVENT_MOUSEDOWN:
            events.push_back({Event::Kind::mouse_down, e->button == 2 ? 1 : e->button == 1 ? 2 : 0, x, y});
            return EM_TRUE;
        case EMSCRIPTEN_EVENT_MOUSEUP:
            events.push_back({Event::Kind::mouse_up, e->button == 2 ? 1 : e->button == 1 ? 2 : 0, x, y});
            return EM_TRUE;
        case EMSCRIPTEN_EVENT_MOUSEMOVE:
            events.push_back({Event::Kind::mouse_move, 0, x, y});
            return EM_TRUE;
        default:
            events.push_back({Event::Kind::leave});
            return EM_FALSE;
    }
}

EM_BOOL on_wheel(int, const EmscriptenWheelEvent* e, void* data) {
    // Pixels (most mice and touchpads) or lines; ImGui scrolls by its own lines.
    const double unit = e->deltaMode == DOM_DELTA_PIXEL ? 100.0 : e->deltaMode == DOM_DELTA_LINE ? 3.0 : 1.0;
    auto& events = static_cast<Display::Platform*>(data)->events;
    events.push_back(
        {Event::Kind::wheel, 0, static_cast<float>(-e->deltaX / unit), static_cast<float>(-e->deltaY / unit)});
    return EM_TRUE;
}

EM_BOOL on_blur(int, const EmscriptenFocusEvent*, void* data) {
    static_cast<Display::Platform*>(data)->events.push_back({Event::Kind::blur});
    return EM_FALSE;
}

const char* css_cursor(ImGuiMouseCursor cursor) {
    switch (cursor) {
        case ImGuiMouseCursor_TextInput:
            return "text";
        case ImGuiMouseCursor_ResizeEW:
            return "ew-resize";
        case ImGuiMouseCursor_ResizeNS:
            return "ns-resize";
        case ImGuiMouseCursor_ResizeAll:
            return "move";
        case ImGuiMouseCursor_Hand:
            return "pointer";
        case ImGuiMouseCursor_NotAllowed:
            return "not-allowed";
        case ImGuiMouseCursor_None:
            return "none";
        default:
            return "default";
    }
}

}  // namespace

bool display_available() {
    return true;  // the page's canvas
}

Display::Display(const DisplayOptions& options) : platform_(std::make_unique<Platform>()), headless_(false) {
    (void)options;  // the page decides the canvas's size and title
    Platform& p = *platform_;
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    attributes.alpha = EM_FALSE;
    attributes.depth = EM_FALSE;
    attributes.antialias = EM_FALSE;  // ImGui anti-aliases its own lines and fills
    p.context = emscripten_webgl_create_context(canvas, &attributes);
    if (p.context <= 0) throw DisplayError("this browser gives the page no WebGL 2 context");
    emscripten_webgl_make_context_current(p.context);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    p.pixel_ratio = static_cast<float>(emscripten_get_device_pixel_ratio());
    font_note_ = set_up_imgui(p.pixel_ratio);
    ImGuiStyle& style = ImGui::GetStyle();
    // As on the desktop: the panels' background is the cleared screen, drawn once.
    p.background = style.Colors[ImGuiCol_WindowBg];
    style.Colors[ImGuiCol_WindowBg].w = 0.0f;
    ImGuiIO& io = ImGui::GetIO();
    io.BackendPlatformName = "impulse_html5";
    io.BackendFlags |= ImGuiBackendFlags_HasMouseCursors;
    // ImGui 1.86 reads its keys by index: the same SDL scancodes (USB usages) the SDL backend maps.
    io.KeyMap[ImGuiKey_Tab] = key::tab;
    io.KeyMap[ImGuiKey_LeftArrow] = key::left;
    io.KeyMap[ImGuiKey_RightArrow] = key::right;
    io.KeyMap[ImGuiKey_UpArrow] = key::up;
    io.KeyMap[ImGuiKey_DownArrow] = key::down;
    io.KeyMap[ImGuiKey_PageUp] = key::page_up;
    io.KeyMap[ImGuiKey_PageDown] = key::page_down;
    io.KeyMap[ImGuiKey_Home] = key::home;
    io.KeyMap[ImGuiKey_End] = key::end;
    io.KeyMap[ImGuiKey_Insert] = key::insert;
    io.KeyMap[ImGuiKey_Delete] = key::del;
    io.KeyMap[ImGuiKey_Backspace] = key::backspace;
    io.KeyMap[ImGuiKey_Space] = key::space;
    io.KeyMap[ImGuiKey_Enter] = key::enter;
    io.KeyMap[ImGuiKey_Escape] = key::escape;
    io.KeyMap[ImGuiKey_KeyPadEnter] = key::keypad_enter;
    io.KeyMap[ImGuiKey_A] = key::a;
    io.KeyMap[ImGuiKey_C] = key::c;
    io.KeyMap[ImGuiKey_V] = key::v;
    io.KeyMap[ImGuiKey_X] = key::x;
    io.KeyMap[ImGuiKey_Y] = key::y;
    io.KeyMap[ImGuiKey_Z] = key::z;
    ImGui_ImplOpenGL3_Init("#version 300 es");
    p.imgui_ready = true;

    emscripten_set_keydown_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, &p, EM_TRUE, on_key);
    emscripten_set_keyup_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, &p, EM_TRUE, on_key);
    emscripten_set_mousedown_callback(canvas, &p, EM_TRUE, on_mouse);
    emscripten_set_mouseup_callback(canvas, &p, EM_TRUE, on_mouse);
    emscripten_set_mousemove_callback(canvas, &p, EM_TRUE, on_mouse);
    emscripten_set_mouseleave_callback(canvas, &p, EM_TRUE, on_mouse);
    emscripten_set_wheel_callback(canvas, &p, EM_TRUE, on_wheel);
    emscripten_set_blur_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, &p, EM_TRUE, on_blur);
    p.last_time = emscripten_get_now();
    live_platform = &p;
}

Display::~Display() {
    Platform& p = *platform_;
    emscripten_html5_remove_all_event_listeners();
    if (live_platform == &p) live_platform = nullptr;
    if (p.imgui_ready) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui::DestroyContext();
    }
    if (p.context > 0) emscripten_webgl_destroy_context(p.context);
}

bool Display::events_waiting() const {
    return !platform_->events.empty() || platform_->resized();
}

bool Display::begin_frame(bool) {
    Platform& p = *platform_;
    ImGuiIO& io = ImGui::GetIO();
    had_events_ = !p.events.empty();
    pressed_keys_.clear();

    // The canvas fills the window: its size in layout pixels, its buffer in the screen's.
    double css_width = 0.0, css_height = 0.0;
    emscripten_get_element_css_size(canvas, &css_width, &css_height);
    const double ratio = emscripten_get_device_pixel_ratio();
    const int width = static_cast<int>(std::lround(css_width * ratio)),
              height = static_cast<int>(std::lround(css_height * ratio));
    if (width != p.buffer_width || height != p.buffer_height) {
        emscripten_set_canvas_element_size(canvas, width, height);
        p.buffer_width = width, p.buffer_height = height;
        had_events_ = true;
    }
    io.DisplaySize = ImVec2(static_cast<float>(css_width), static_cast<float>(css_height));
    io.DisplayFramebufferScale = ImVec2(css_width > 0 ? static_cast<float>(width / css_width) : 1.0f,
                                        css_height > 0 ? static_cast<float>(height / css_height) : 1.0f);
    // Moved to a screen of another density (or zoomed): the fonts again, for the new one.
    if (std::fabs(static_cast<float>(ratio) - p.pixel_ratio) > 0.01f) {
        p.pixel_ratio = static_cast<float>(ratio);
        io.Fonts->Clear();
        load_fonts(io, p.pixel_ratio);
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }

    // A release of a key or button pressed in this frame waits, with everything after it, for the next frame:
    // ImGui 1.86 reads whether a key or button is down once per frame, so a press and its release in one frame (a
    // quick tap, or a test's click) would never reach a widget. Cutting the queue there, rather than holding back
    // only the release, keeps the order: text typed right after Ctrl+A is not read as typed with Ctrl held.
    std::vector<int> buttons_pressed;
    std::size_t taken = 0;
    for (; taken < p.events.size(); ++taken) {
        const Event& e = p.events[taken];
        const bool tap_ends =
            (e.kind == Event::Kind::key_up &&
             std::find(pressed_keys_.begin(), pressed_keys_.end(), e.code) != pressed_keys_.end()) ||
            (e.kind == Event::Kind::mouse_up &&
             std::find(buttons_pressed.begin(), buttons_pressed.end(), e.code) != buttons_pressed.end());
        if (tap_ends) break;
        switch (e.kind) {
            case Event::Kind::key_down:
                io.KeysDown[e.code] = true;
                pressed_keys_.push_back(e.code);
                break;
            case Event::Kind::key_up:
                io.KeysDown[e.code] = false;
                break;
            case Event::Kind::text:
                io.AddInputCharactersUTF8(e.text.c_str());
                break;
            case Event::Kind::mouse_down:
                io.MousePos = ImVec2(e.x, e.y);
                io.MouseDown[e.code] = true;
                buttons_pressed.push_back(e.code);
                break;
            case Event::Kind::mouse_up:
                io.MousePos = ImVec2(e.x, e.y);
                io.MouseDown[e.code] = false;
                break;
            case Event::Kind::mouse_move:
                io.MousePos = ImVec2(e.x, e.y);
                break;
            case Event::Kind::wheel:
                io.MouseWheelH += e.x;
                io.MouseWheel += e.y;
                break;
            case Event::Kind::leave:
                io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
                break;
            case Event::Kind::blur:  // keys released while the page had no focus never arrive
                for (bool& down : io.KeysDown) down = false;
                for (bool& down : io.MouseDown) down = false;
                break;
        }
    }
    p.events.erase(p.events.begin(), p.events.begin() + static_cast<std::ptrdiff_t>(taken));
    io.KeyCtrl = io.KeysDown[key::left_ctrl] || io.KeysDown[key::right_ctrl];
    io.KeyShift = io.KeysDown[key::left_shift] || io.KeysDown[key::right_shift];
    io.KeyAlt = io.KeysDown[key::left_alt] || io.KeysDown[key::right_alt];
    io.KeySuper = io.KeysDown[key::left_gui] || io.KeysDown[key::right_gui];

    const double now = emscripten_get_now();
    io.DeltaTime = static_cast<float>(std::max(now - p.last_time, 1.0) / 1000.0);
    p.last_time = now;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    return true;
}

void Display::end_frame(Pixels* capture) {
    Platform& p = *platform_;
    ImGui::Render();
    glViewport(0, 0, p.buffer_width, p.buffer_height);
    glClearColor(p.background.x, p.background.y, p.background.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (capture) {
        const int width = p.buffer_width, height = p.buffer_height;
        capture->width = width;
        capture->height = height;
        std::vector<unsigned char> bottom_up(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
        capture->rgba.resize(bottom_up.size());
        const std::size_t row = static_cast<std::size_t>(width) * 4;
        for (int y = 0; y < height; ++y)  // GL's first row is the bottom one
            std::copy_n(bottom_up.data() + static_cast<std::size_t>(height - 1 - y) * row, row,
                        capture->rgba.data() + static_cast<std::size_t>(y) * row);
    }
    const ImGuiMouseCursor cursor = ImGui::GetMouseCursor();
    if (cursor != p.cursor) {
        p.cursor = cursor;
        set_canvas_cursor(css_cursor(cursor));
    }
    // The browser shows the frame when this function's caller returns to it: no swap.
}

// A script's keys and text (gui/key_events.hpp) as the page's would come: on the display's own queue. The chord
// names SDL's keys, as on the desktop; they are read here as the KeyboardEvent codes the page gives.
void push_key(const std::string& chord) {
    std::string name = chord;
    std::vector<int> modifiers;
    const auto lower = [](std::string text) {
        for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return text;
    };
    for (bool found = true; found;) {
        found = false;
        for (const auto& [prefix, usage] : {std::pair<std::string_view, int>{"ctrl+", key::left_ctrl},
                                            std::pair<std::string_view, int>{"shift+", key::left_shift},
                                            std::pair<std::string_view, int>{"alt+", key::left_alt}})
            if (lower(name).starts_with(prefix)) {
                modifiers.push_back(usage);
                name.erase(0, prefix.size());
                found = true;
            }
    }
    struct Alias {
        std::string_view sdl, code;
    };
    constexpr Alias aliases[] = {
        {"right", "ArrowRight"},
        {"left", "ArrowLeft"},
        {"up", "ArrowUp"},
        {"down", "ArrowDown"},
        {"return", "Enter"},
        {"enter", "Enter"},
        {"tab", "Tab"},
        {"escape", "Escape"},
        {"esc", "Escape"},
        {"pagedown", "PageDown"},
        {"page down", "PageDown"},
        {"pgdn", "PageDown"},
        {"pageup", "PageUp"},
        {"page up", "PageUp"},
        {"pgup", "PageUp"},
        {"home", "Home"},
        {"end", "End"},
        {"backspace", "Backspace"},
        {"delete", "Delete"},
        {"space", "Space"},
        {"keypad enter", "NumpadEnter"},
    };
    std::string code;
    for (const Alias& a : aliases)
        if (lower(name) == a.sdl) code = a.code;
    if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0])))
        code = std::string("Key") + static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
    if (name.size() == 1 && std::isdigit(static_cast<unsigned char>(name[0]))) code = "Digit" + name;
    const int usage = code.empty() ? 0 : scancode(code);
    if (usage == 0)
        throw formats::InputError("key", "\"" + chord +
                                             "\" is not a key: use SDL's names (Right, Left, Return, Tab, Escape, "
                                             "PageDown, A, 1, ...), perhaps after ctrl+, shift+ or alt+");
    if (!live_platform) return;
    std::vector<Event>& events = live_platform->events;
    for (const int m : modifiers) events.push_back({Event::Kind::key_down, m});
    events.push_back({Event::Kind::key_down, usage});
    events.push_back({Event::Kind::key_up, usage});
    for (const int m : modifiers) events.push_back({Event::Kind::key_up, m});
}

void push_text(const std::string& text) {
    if (live_platform) live_platform->events.push_back({Event::Kind::text, 0, 0, 0, text});
}

}  // namespace impulse::gui
