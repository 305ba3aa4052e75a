// The site's program: the page's module starts it once its files are in place (index.html); it opens the canvas,
// then draws a frame whenever the page asks for one. The page calls the functions below for what happens outside
// the canvas: the address changed, a file was picked or dropped, a test reads the state.

#include "web/page.hpp"
#include "web/site.hpp"

#include <emscripten/emscripten.h>

#include <exception>
#include <iostream>
#include <memory>
#include <string>

namespace {

std::unique_ptr<impulse::web::Site> site;
std::string answer;  // the last text handed to the page

void frame() {
    try {
        site->frame();
    } catch (const std::exception& e) {
        // Nothing should reach here; if something does, the page says so (and the browser test fails on it).
        std::cerr << "impulse-lab: " << e.what() << std::endl;
        site->route("");
    }
}

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE void impulse_route(const char* fragment) {
    if (site) site->route(fragment);
}

// purpose: 0 a scene, case or trace to open; 1 progress to import.
EMSCRIPTEN_KEEPALIVE void impulse_file_picked(const char* path, int purpose) {
    if (site) site->file_picked(path, purpose == 1);
}

EMSCRIPTEN_KEEPALIVE const char* impulse_test_state() {
    answer = site ? site->test_state() : std::string("{}");
    return answer.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* impulse_layout_check(int width, int height) {
    answer = site ? site->layout_check(width, height) : std::string("the site did not start");
    return answer.c_str();
}

}  // extern "C"

int main() {
    try {
        site = std::make_unique<impulse::web::Site>();
    } catch (const std::exception& e) {
        impulse::web::failed(e.what());
        return 1;
    }
    site->route(impulse::web::fragment());
    impulse::web::ready();
    emscripten_set_main_loop(frame, 0, false);
    return 0;
}
