// The inspector's window on the desktop: SDL2, with an OpenGL 3.2 core context; headless, SDL's offscreen driver
// (EGL and Mesa). The browser's counterpart is web/display_web.cpp.

#include "gui/display.hpp"

#include "gui/keys.hpp"

#include <SDL.h>
#include <SDL_opengl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>
#include <imgui_impl_sdl.h>

#include <algorithm>
#include <cstdlib>

namespace impulse::gui {

// The panels read keys by their USB HID usage numbers (gui/keys.hpp), which SDL's scancodes are.
static_assert(key::right == SDL_SCANCODE_RIGHT && key::left == SDL_SCANCODE_LEFT && key::down == SDL_SCANCODE_DOWN &&
              key::up == SDL_SCANCODE_UP && key::page_down == SDL_SCANCODE_PAGEDOWN &&
              key::page_up == SDL_SCANCODE_PAGEUP && key::home == SDL_SCANCODE_HOME && key::end == SDL_SCANCODE_END &&
              key::enter == SDL_SCANCODE_RETURN && key::keypad_enter == SDL_SCANCODE_KP_ENTER &&
              key::tab == SDL_SCANCODE_TAB && key::escape == SDL_SCANCODE_ESCAPE && key::a == SDL_SCANCODE_A &&
              key::s == SDL_SCANCODE_S && key::z == SDL_SCANCODE_Z && key::left_ctrl == SDL_SCANCODE_LCTRL &&
              key::right_gui == SDL_SCANCODE_RGUI);

namespace {

// The few GL calls made outside ImGui's backend, looked up through SDL so the program does not link libGL.
struct GlCalls {
    void(APIENTRY* viewport)(GLint, GLint, GLsizei, GLsizei);
    void(APIENTRY* clear_color)(GLfloat, GLfloat, GLfloat, GLfloat);
    void(APIENTRY* clear)(GLbitfield);
    void(APIENTRY* read_pixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
    void(APIENTRY* pixel_store)(GLenum, GLint);
    void(APIENTRY* finish)();
};

template <typename F>
void look_up(F& function, const char* name) {
    function = reinterpret_cast<F>(SDL_GL_GetProcAddress(name));
    if (!function) throw DisplayError(std::string("OpenGL function ") + name + " is missing");
}

bool set(const char* name) {
    const char* value = std::getenv(name);
    return value && *value;
}

}  // namespace

struct Display::Platform {
    GlCalls gl{};
    SDL_Window* window = nullptr;
    void* gl_context = nullptr;
    bool imgui_ready = false;
    bool quit = false;
    std::vector<SDL_Event> deferred;  // key releases passed to ImGui a frame after their press
    ImVec4 window_background{};
};

bool display_available() {
    return set("DISPLAY") || set("WAYLAND_DISPLAY");
}

Display::Display(const DisplayOptions& options) : platform_(std::make_unique<Platform>()), headless_(options.headless) {
    Platform& p = *platform_;
    // Headless: SDL's offscreen driver, even when a display exists. With an X display and no Wayland one,
    // ask for X11 directly, so SDL does not try Wayland first and print its complaints.
    if (headless_)
        SDL_SetHint(SDL_HINT_VIDEODRIVER, "offscreen");
    else if (set("DISPLAY") && !set("WAYLAND_DISPLAY"))
        SDL_SetHint(SDL_HINT_VIDEODRIVER, "x11");
    if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) != 0)
        throw DisplayError(std::string("cannot start SDL video: ") + SDL_GetError());

    SDL_GL_SetAttribute(SDL_GL_CONTEXT_FLAGS, 0);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 2);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
    SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 8);
    const Uint32 flags = SDL_WINDOW_OPENGL | (headless_ ? 0u : SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    int width = options.width, height = options.height;
    // A laptop's 1024x768 must not cut the window on three sides: 90 % of what the display leaves free.
    if (SDL_Rect usable{}; options.fit_to_screen && !headless_ && SDL_GetDisplayUsableBounds(0, &usable) == 0 &&
                           usable.w > 0 && usable.h > 0) {
        width = std::max(usable.w * 9 / 10, 320);
        height = std::max(usable.h * 9 / 10, 240);
    }
    p.window =
        SDL_CreateWindow(options.title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, flags);
    if (!p.window) {
        const std::string why = SDL_GetError();
        SDL_Quit();
        throw DisplayError("cannot open a window: " + why);
    }
    p.gl_context = SDL_GL_CreateContext(p.window);
    if (!p.gl_context) {
        const std::string why = SDL_GetError();
        SDL_DestroyWindow(p.window);
        SDL_Quit();
        throw DisplayError("cannot create an OpenGL 3.2 context: " + why);
    }
    SDL_GL_MakeCurrent(p.window, p.gl_context);
    SDL_GL_SetSwapInterval(headless_ ? 0 : 1);  // a window follows the screen's refresh; headless runs free
    try {
        look_up(p.gl.viewport, "glViewport");
        look_up(p.gl.clear_color, "glClearColor");
        look_up(p.gl.clear, "glClear");
        look_up(p.gl.read_pixels, "glReadPixels");
        look_up(p.gl.pixel_store, "glPixelStorei");
        look_up(p.gl.finish, "glFinish");
    } catch (...) {
        SDL_GL_DeleteContext(p.gl_context);
        SDL_DestroyWindow(p.window);
        SDL_Quit();
        throw;
    }

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    font_note_ = set_up_imgui();
    ImGuiStyle& style = ImGui::GetStyle();
    // The panels tile the screen, so their background is the cleared screen itself: ImGui skips a fully
    // transparent background, which saves shading every pixel twice (llvmpipe renders headless frames on
    // the CPU, where that is a third of the frame time).
    p.window_background = style.Colors[ImGuiCol_WindowBg];
    style.Colors[ImGuiCol_WindowBg].w = 0.0f;
    ImGui_ImplSDL2_InitForOpenGL(p.window, p.gl_context);
    ImGui_ImplOpenGL3_Init("#version 150");
    p.imgui_ready = true;
}

Display::~Display() {
    Platform& p = *platform_;
    if (p.imgui_ready) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplSDL2_Shutdown();
        ImGui::DestroyContext();
    }
    if (p.gl_context) SDL_GL_DeleteContext(p.gl_context);
    if (p.window) SDL_DestroyWindow(p.window);
    SDL_Quit();
}

bool Display::events_waiting() const {
    return !platform_->deferred.empty() || SDL_HasEvents(SDL_FIRSTEVENT, SDL_LASTEVENT);
}

bool Display::begin_frame(bool idle) {
    Platform& p = *platform_;
    if (idle && !headless_ && p.deferred.empty()) SDL_WaitEventTimeout(nullptr, 250);
    SDL_Event event;
    had_events_ = !p.deferred.empty();
    pressed_keys_.clear();
    // Key releases held back from the last frame: ImGui 1.86 reads whether a key is down once per frame, so
    // a press and its release in one frame (a quick tap, or a test's synthetic keys) would never reach a
    // widget (Enter in the answer field, Ctrl+A). The release comes a frame after its press instead.
    std::vector<SDL_Event> releases;
    releases.swap(p.deferred);
    // ImGui reads the modifiers from SDL's keyboard state; a key event carries its own, which a key put on the
    // queue by a script (gui/key_events.hpp) must bring along.
    const auto process = [](SDL_Event& e) {
        if (e.type == SDL_KEYDOWN || e.type == SDL_KEYUP) SDL_SetModState(static_cast<SDL_Keymod>(e.key.keysym.mod));
        ImGui_ImplSDL2_ProcessEvent(&e);
    };
    for (SDL_Event& e : releases) process(e);
    std::vector<SDL_Scancode> down;
    while (SDL_PollEvent(&event)) {
        had_events_ = true;
        if (event.type == SDL_KEYDOWN) {
            pressed_keys_.push_back(event.key.keysym.scancode);
            down.push_back(event.key.keysym.scancode);
        }
        if (event.type == SDL_KEYUP && std::find(down.begin(), down.end(), event.key.keysym.scancode) != down.end()) {
            p.deferred.push_back(event);
            continue;
        }
        process(event);
        if (event.type == SDL_QUIT) p.quit = true;
        if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE &&
            event.window.windowID == SDL_GetWindowID(p.window))
            p.quit = true;
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    // Headless frames do not depend on how long the previous one took: the same script gives the same
    // pictures on any machine.
    if (headless_) ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    return !p.quit;
}

void Display::end_frame(Pixels* capture) {
    Platform& p = *platform_;
    ImGui::Render();
    const ImGuiIO& io = ImGui::GetIO();
    const int width = static_cast<int>(io.DisplaySize.x * io.DisplayFramebufferScale.x);
    const int height = static_cast<int>(io.DisplaySize.y * io.DisplayFramebufferScale.y);
    p.gl.viewport(0, 0, width, height);
    p.gl.clear_color(p.window_background.x, p.window_background.y, p.window_background.z, 1.0f);
    p.gl.clear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    // Headless, a frame counts as done when it is drawn, not when it was queued: frame times are honest.
    if (headless_) p.gl.finish();
    if (capture) {
        capture->width = width;
        capture->height = height;
        std::vector<unsigned char> bottom_up(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
        p.gl.pixel_store(GL_PACK_ALIGNMENT, 1);
        p.gl.read_pixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
        // GL's first row is the bottom one.
        capture->rgba.resize(bottom_up.size());
        const std::size_t row = static_cast<std::size_t>(width) * 4;
        for (int y = 0; y < height; ++y)
            std::copy_n(bottom_up.data() + static_cast<std::size_t>(height - 1 - y) * row, row,
                        capture->rgba.data() + static_cast<std::size_t>(y) * row);
        for (std::size_t i = 3; i < capture->rgba.size(); i += 4) capture->rgba[i] = 255;  // opaque
    }
    SDL_GL_SwapWindow(p.window);
}

}  // namespace impulse::gui
