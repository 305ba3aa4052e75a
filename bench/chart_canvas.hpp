#pragma once
// The canvas the bench's charts are drawn on: a Dear ImGui draw list in a context of its own with no window and
// no backend, its draw data rendered on the CPU (bench/draw_data_raster) and encoded as PNG. It needs no display,
// SDL or OpenGL, so the bench writes its pictures anywhere it runs.

#include <imgui.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace impulse::bench {

// Why a chart could not be written, as one line.
class ChartError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A `width` x `height` picture, white, with `draw` adding to its draw list; ImGui::GetFont() is DejaVu Sans at
// 15 px (ImGui's built-in font when fonts-dejavu-core is missing) while `draw` runs. Returns the PNG file's bytes;
// throws ChartError when they cannot be encoded. The caller's ImGui context, if any, is current again afterwards.
std::string draw_png(int width, int height, const std::function<void(ImDrawList&)>& draw);

}  // namespace impulse::bench
