#include "gui/fonts.hpp"

#include <imgui.h>

#include <cmath>
#include <filesystem>

namespace impulse::gui {

namespace {

// Debian's fonts-dejavu-core (scripts/install-deps installs it).
constexpr const char* sans_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* mono_path = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr float font_size = 15.0f;

// The combining dot above (θ̇, the angular velocity). ImGui places a combining mark where the font puts it for a
// lower-case letter, with no anchor for the letter before it: DejaVu's dot then lands inside θ's top stroke and
// θ̇ reads as θ. The dot is drawn by the inspector instead, above a letter of full height.
constexpr ImWchar combining_dot = 0x0307;

// Latin with its extensions (ŷ, ṗ, ẑ), Greek, the combining accents but the dot, general punctuation (the middle
// dot, dashes), sub- and superscripts, letter-like symbols, arrows, mathematical operators, modifier letters (ᵀ),
// the geometric shapes of the buttons (◀ ▶ ●) and the check mark of the step list (✓).
constexpr ImWchar glyph_ranges[] = {
    0x0020, 0x017F, 0x1E00, 0x1EFF, 0x0300, 0x0306, 0x0308, 0x036F, 0x0370, 0x03FF, 0x1D00, 0x1DBF, 0x2000, 0x206F,
    0x2070, 0x209F, 0x2100, 0x214F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0x25A0, 0x25FF, 0x2713, 0x2713, 0,
};

struct DotGlyph {
    int rect;
    int size;
};

// A round dot `size` pixels wide, its centre over the middle of the letter before it (about a quarter of an em
// back from the pen) and a pixel of gap above the letters' tops.
// `pixels`: the font's size in layout pixels (ImFont::FontSize is only set when the atlas is built); the atlas
// holds it `pixel_ratio` times larger, so the dot and its offsets are that much larger too.
DotGlyph add_dot(ImFontAtlas& atlas, ImFont* font, float pixels, float pixel_ratio) {
    const int size = static_cast<int>(std::lround((pixels >= 14.0f ? 3.0f : 2.0f) * pixel_ratio));
    const float centre = -0.26f * pixels * pixel_ratio;
    const int rect = atlas.AddCustomRectFontGlyph(
        font, combining_dot, size, size, 0.0f, ImVec2(centre - static_cast<float>(size) / 2.0f, -2.0f * pixel_ratio));
    return {rect, size};
}

void draw_dot(ImFontAtlas& atlas, const DotGlyph& dot) {
    const ImFontAtlasCustomRect* r = atlas.GetCustomRectByIndex(dot.rect);
    for (int y = 0; y < dot.size; ++y)
        for (int x = 0; x < dot.size; ++x) {
            // A 3-pixel dot with its corners half covered reads as round; a larger one (a dense screen) is a disc.
            const float radius = static_cast<float>(dot.size) / 2.0f, dx = static_cast<float>(x) + 0.5f - radius,
                        dy = static_cast<float>(y) + 0.5f - radius;
            const bool corner =
                dot.size == 3 ? (x == 0 || x == 2) && (y == 0 || y == 2) : dx * dx + dy * dy > radius * radius;
            atlas.TexPixelsAlpha8[(r->Y + y) * atlas.TexWidth + r->X + x] = corner ? 0x70 : 0xFF;
        }
}

}  // namespace

std::string load_fonts(ImGuiIO& io, float pixel_ratio) {
    io.FontGlobalScale = 1.0f / pixel_ratio;
    if (!std::filesystem::exists(sans_path) || !std::filesystem::exists(mono_path)) {
        ImFontConfig config;
        config.SizePixels = 13.0f * pixel_ratio;
        io.Fonts->AddFontDefault(&config);
        return "the DejaVu fonts are missing (Debian package fonts-dejavu-core): symbols such as Δ show as '?'";
    }
    const float sans_pixels = font_size * pixel_ratio, mono_pixels = (font_size - 1.0f) * pixel_ratio;
    ImFont* sans = io.Fonts->AddFontFromFileTTF(sans_path, sans_pixels, nullptr, glyph_ranges);
    ImFont* mono = io.Fonts->AddFontFromFileTTF(mono_path, mono_pixels, nullptr, glyph_ranges);
    const DotGlyph dots[] = {add_dot(*io.Fonts, sans, font_size, pixel_ratio),
                             add_dot(*io.Fonts, mono, font_size - 1.0f, pixel_ratio)};
    // Built here, once, so the dots can be drawn into the atlas before a renderer uploads it.
    io.Fonts->Build();
    for (const DotGlyph& dot : dots) draw_dot(*io.Fonts, dot);
    return {};
}

ImFont* value_font() {
    ImFontAtlas* atlas = ImGui::GetIO().Fonts;
    return atlas->Fonts.Size > 1 ? atlas->Fonts[1] : atlas->Fonts[0];
}

}  // namespace impulse::gui
