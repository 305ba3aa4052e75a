#pragma once
// Dear ImGui's draw data rendered on the CPU into an RGBA image, the way ImGui's OpenGL 3 backend has the GPU
// render it, so the bench draws its charts with no display, SDL, EGL or OpenGL: triangles sampled at pixel
// centres with the top-left fill rule, per-vertex colour times a bilinear texture sample, each command's clip
// rectangle as a scissor, and "over" blending (colour: source alpha, 1 - source alpha; alpha: 1, 1 - source
// alpha) into 8 bits per channel. No antialiasing beyond the fringe triangles ImGui draws itself.

#include <imgui.h>

#include <string>
#include <vector>

namespace impulse::bench {

// A picture, 8 bits per channel, top row first.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<unsigned char> rgba;  // width * height * 4

    Image() = default;
    Image(int width, int height, ImU32 fill);  // every pixel `fill` (IM_COL32 order: r, g, b, a)
    ImU32 at(int x, int y) const;              // IM_COL32 order
};

// What a draw command's TextureId points at: RGBA, 8 bits per channel, top row first, not owned. A null
// TextureId samples as opaque white, so untextured geometry needs no texture.
struct Texture {
    int width = 0;
    int height = 0;
    const unsigned char* rgba = nullptr;
};

// Draws every command list of `data` over `image` in order. Positions are ImGui's: (pos - DisplayPos) *
// FramebufferScale gives pixels, with pixel (x, y) covering [x, x + 1) x [y, y + 1). Each TextureId must be null
// or point at a Texture that outlives the call; commands with a user callback are not supported (the charts
// add none) and are skipped.
void rasterize(const ImDrawData& data, Image& image);

// The image as PNG file bytes; empty when the encoder failed.
std::string png_bytes(const Image& image);

}  // namespace impulse::bench
