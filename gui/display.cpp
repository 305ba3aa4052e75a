#include "gui/display.hpp"

#include "gui/fonts.hpp"

#include <SDL.h>
#include <SDL_opengl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>
#include <imgui_impl_sdl.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>

namespace impulse::gui {

// The few GL calls made outside ImGui's backend, looked up through SDL so the program does not link libGL.
struct GlCalls {
    void(APIENTRY* viewport)(GLint, GLint, GLsizei, GLsizei);
    void(APIENTRY* clear_color)(GLfloat, GLfloat, GLfloat, GLfloat);
    void(APIENTRY* clear)(GLbitfield);
    void(APIENTRY* read_pixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
    void(APIENTRY* pixel_store)(GLenum, GLint);
    void(APIENTRY* finish)();
};

namespace {

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

std::string set_up_imgui() {
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // never write imgui.ini into the user's working directory
    io.LogFilename = nullptr;
    const std::string note = load_fonts(io);
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    return note;
}

bool display_available() {
    return set("DISPLAY") || set("WAYLAND_DISPLAY");
}

Display::Display(const DisplayOptions& options) : headless_(options.headless), gl_(std::make_unique<GlCalls>()) {
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
    window_ =
        SDL_CreateWindow(options.title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, flags);
    if (!window_) {
        const std::string why = SDL_GetError();
        SDL_Quit();
        throw DisplayError("cannot open a window: " + why);
    }
    gl_context_ = SDL_GL_CreateContext(window_);
    if (!gl_context_) {
        const std::string why = SDL_GetError();
        SDL_DestroyWindow(window_);
        SDL_Quit();
        throw DisplayError("cannot create an OpenGL 3.2 context: " + why);
    }
    SDL_GL_MakeCurrent(window_, gl_context_);
    SDL_GL_SetSwapInterval(headless_ ? 0 : 1);  // a window follows the screen's refresh; headless runs free
    try {
        look_up(gl_->viewport, "glViewport");
        look_up(gl_->clear_color, "glClearColor");
        look_up(gl_->clear, "glClear");
        look_up(gl_->read_pixels, "glReadPixels");
        look_up(gl_->pixel_store, "glPixelStorei");
        look_up(gl_->finish, "glFinish");
    } catch (...) {
        SDL_GL_DeleteContext(gl_context_);
        SDL_DestroyWindow(window_);
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
    const ImVec4 bg = style.Colors[ImGuiCol_WindowBg];
    window_background_ = {bg.x, bg.y, bg.z, bg.w};
    style.Colors[ImGuiCol_WindowBg].w = 0.0f;
    ImGui_ImplSDL2_InitForOpenGL(window_, gl_context_);
    ImGui_ImplOpenGL3_Init("#version 150");
    imgui_ready_ = true;
}

Display::~Display() {
    if (imgui_ready_) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplSDL2_Shutdown();
        ImGui::DestroyContext();
    }
    if (gl_context_) SDL_GL_DeleteContext(gl_context_);
    if (window_) SDL_DestroyWindow(window_);
    SDL_Quit();
}

bool Display::begin_frame(bool idle) {
    if (idle && !headless_ && deferred_.empty()) SDL_WaitEventTimeout(nullptr, 250);
    SDL_Event event;
    had_events_ = !deferred_.empty();
    pressed_keys_.clear();
    // Key releases held back from the last frame: ImGui 1.86 reads whether a key is down once per frame, so
    // a press and its release in one frame (a quick tap, or a test's synthetic keys) would never reach a
    // widget (Enter in the answer field, Ctrl+A). The release comes a frame after its press instead.
    std::vector<SDL_Event> releases;
    releases.swap(deferred_);
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
            deferred_.push_back(event);
            continue;
        }
        process(event);
        if (event.type == SDL_QUIT) quit_ = true;
        if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE &&
            event.window.windowID == SDL_GetWindowID(window_))
            quit_ = true;
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    // Headless frames do not depend on how long the previous one took: the same script gives the same
    // pictures on any machine.
    if (headless_) ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    return !quit_;
}

void Display::end_frame(Pixels* capture) {
    ImGui::Render();
    const ImGuiIO& io = ImGui::GetIO();
    const int width = static_cast<int>(io.DisplaySize.x * io.DisplayFramebufferScale.x);
    const int height = static_cast<int>(io.DisplaySize.y * io.DisplayFramebufferScale.y);
    gl_->viewport(0, 0, width, height);
    gl_->clear_color(window_background_.x, window_background_.y, window_background_.z, 1.0f);
    gl_->clear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    // Headless, a frame counts as done when it is drawn, not when it was queued: frame times are honest.
    if (headless_) gl_->finish();
    if (capture) {
        capture->width = width;
        capture->height = height;
        std::vector<unsigned char> bottom_up(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
        gl_->pixel_store(GL_PACK_ALIGNMENT, 1);
        gl_->read_pixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
        // GL's first row is the bottom one.
        capture->rgba.resize(bottom_up.size());
        const std::size_t row = static_cast<std::size_t>(width) * 4;
        for (int y = 0; y < height; ++y)
            std::copy_n(bottom_up.data() + static_cast<std::size_t>(height - 1 - y) * row, row,
                        capture->rgba.data() + static_cast<std::size_t>(y) * row);
        for (std::size_t i = 3; i < capture->rgba.size(); i += 4) capture->rgba[i] = 255;  // opaque
    }
    SDL_GL_SwapWindow(window_);
}

std::string encode_png(const Pixels& pixels) {
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    stbi_write_png_compression_level = 6;
    stbi_write_force_png_filter = 0;  // about three times faster than trying every filter, a little larger
    if (!stbi_write_png_to_func(append, &bytes, pixels.width, pixels.height, 4, pixels.rgba.data(), pixels.width * 4))
        throw DisplayError("cannot encode the PNG");
    return bytes;
}

}  // namespace impulse::gui
