#include "gui/display.hpp"

#include "gui/fonts.hpp"

#include <imgui.h>
#include <stb_image_write.h>

namespace impulse::gui {

std::string set_up_imgui(float pixel_ratio) {
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // never write imgui.ini into the user's working directory
    io.LogFilename = nullptr;
    const std::string note = load_fonts(io, pixel_ratio);
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    return note;
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
