#include "bench/chart_canvas.hpp"

#include "bench/draw_data_raster.hpp"

#include <filesystem>

namespace impulse::bench {

namespace {

// The inspector's text font (Debian's fonts-dejavu-core), with the Latin letters, the general punctuation (the
// dashes) and the arrows and operators the charts' labels use (×, ≤).
constexpr const char* sans_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr float font_size = 15.0f;
constexpr ImWchar glyph_ranges[] = {0x0020, 0x017F, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};

// An ImGui context for one picture, made current, and the caller's context back when it goes.
class Context {
public:
    Context() : previous_(ImGui::GetCurrentContext()), own_(ImGui::CreateContext()) { ImGui::SetCurrentContext(own_); }
    ~Context() {
        ImGui::DestroyContext(own_);
        ImGui::SetCurrentContext(previous_);
    }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

private:
    ImGuiContext* previous_;
    ImGuiContext* own_;
};

}  // namespace

std::string draw_png(int width, int height, const std::function<void(ImDrawList&)>& draw) {
    const Context context;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // never write imgui.ini into the user's working directory
    io.LogFilename = nullptr;
    io.DisplaySize = {static_cast<float>(width), static_cast<float>(height)};
    io.DeltaTime = 1.0f / 60.0f;
    // The rasterizer honours each command's vertex offset, so a chart may pass 65536 vertices with 16-bit indices.
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    if (std::filesystem::exists(sans_path))
        io.Fonts->AddFontFromFileTTF(sans_path, font_size, nullptr, glyph_ranges);
    else
        io.Fonts->AddFontDefault();
    unsigned char* atlas_pixels = nullptr;
    int atlas_width = 0, atlas_height = 0;
    io.Fonts->GetTexDataAsRGBA32(&atlas_pixels, &atlas_width, &atlas_height);
    const Texture atlas{atlas_width, atlas_height, atlas_pixels};
    io.Fonts->SetTexID(const_cast<Texture*>(&atlas));  // ImTextureID is void*; the rasterizer only reads it

    ImGui::NewFrame();
    ImDrawList& list = *ImGui::GetBackgroundDrawList();
    draw(list);
    ImGui::Render();

    Image image(width, height, IM_COL32(255, 255, 255, 255));
    rasterize(*ImGui::GetDrawData(), image);
    std::string png = png_bytes(image);
    if (png.empty()) throw ChartError("cannot encode the PNG");
    return png;
}

}  // namespace impulse::bench
