#include "gui/fonts.hpp"

#include <imgui.h>

#include <filesystem>

namespace impulse::gui {

namespace {

// Debian's fonts-dejavu-core (scripts/install-deps installs it).
constexpr const char* sans_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* mono_path = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr float font_size = 15.0f;

// Latin with its extensions (ŷ, ṗ, ẑ), Greek, the combining accents (the dot of θ̇), general punctuation (the
// middle dot, dashes), sub- and superscripts, letter-like symbols, arrows, mathematical operators, modifier
// letters (ᵀ) and the geometric shapes of the buttons (◀ ▶).
constexpr ImWchar glyph_ranges[] = {
    0x0020, 0x017F, 0x1E00, 0x1EFF, 0x0300, 0x036F, 0x0370, 0x03FF, 0x1D00, 0x1DBF, 0x2000, 0x206F,
    0x2070, 0x209F, 0x2100, 0x214F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0x25A0, 0x25FF, 0,
};

}  // namespace

std::string load_fonts(ImGuiIO& io) {
    if (!std::filesystem::exists(sans_path) || !std::filesystem::exists(mono_path)) {
        io.Fonts->AddFontDefault();
        return "the DejaVu fonts are missing (Debian package fonts-dejavu-core): symbols such as Δ show as '?'";
    }
    io.Fonts->AddFontFromFileTTF(sans_path, font_size, nullptr, glyph_ranges);
    io.Fonts->AddFontFromFileTTF(mono_path, font_size - 1.0f, nullptr, glyph_ranges);
    return {};
}

ImFont* value_font() {
    ImFontAtlas* atlas = ImGui::GetIO().Fonts;
    return atlas->Fonts.Size > 1 ? atlas->Fonts[1] : atlas->Fonts[0];
}

}  // namespace impulse::gui
