#include "gui/key_events.hpp"

#include "formats/input_error.hpp"

#include <SDL.h>

#include <algorithm>
#include <cctype>
#include <cstring>

namespace impulse::gui {

namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

}  // namespace

void push_key(const std::string& chord) {
    std::string name = chord;
    Uint16 mod = KMOD_NONE;
    for (const auto& [prefix, bit] :
         {std::pair<const char*, Uint16>{"ctrl+", KMOD_LCTRL}, std::pair<const char*, Uint16>{"shift+", KMOD_LSHIFT},
          std::pair<const char*, Uint16>{"alt+", KMOD_LALT}})
        for (std::size_t at = lower(name).find(prefix); at == 0; at = lower(name).find(prefix)) {
            mod |= bit;
            name.erase(0, std::strlen(prefix));
        }
    // SDL's names for the keys a student presses ("Page Down" for PgDn); "PageDown" and "Enter" read as well.
    if (lower(name) == "pagedown" || lower(name) == "pgdn") name = "PageDown";
    if (lower(name) == "pageup" || lower(name) == "pgup") name = "PageUp";
    if (lower(name) == "enter") name = "Return";
    if (lower(name) == "esc") name = "Escape";
    const SDL_Scancode code = SDL_GetScancodeFromName(name.c_str());
    if (code == SDL_SCANCODE_UNKNOWN)
        throw formats::InputError("key", "\"" + chord +
                                             "\" is not a key: use SDL's names (Right, Left, Return, Tab, Escape, "
                                             "PageDown, A, 1, ...), perhaps after ctrl+, shift+ or alt+");
    for (const Uint32 type : {SDL_KEYDOWN, SDL_KEYUP}) {
        SDL_Event event{};
        event.key.type = type;
        event.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
        event.key.keysym.scancode = code;
        event.key.keysym.sym = SDL_GetKeyFromScancode(code);
        event.key.keysym.mod = mod;
        SDL_PushEvent(&event);
    }
}

void push_text(const std::string& text) {
    // SDL_TEXTINPUT holds up to 31 bytes; cut at a character's start.
    for (std::size_t start = 0; start < text.size();) {
        std::size_t end = std::min(start + 24, text.size());
        while (end < text.size() && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
        SDL_Event event{};
        event.text.type = SDL_TEXTINPUT;
        std::memcpy(event.text.text, text.data() + start, end - start);
        SDL_PushEvent(&event);
        start = end;
    }
}

}  // namespace impulse::gui
