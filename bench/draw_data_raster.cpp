#include "bench/draw_data_raster.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace impulse::bench {

namespace {

// A colour with channels 0..1, as the GPU holds a normalized 8-bit value.
struct Colour {
    float r = 0, g = 0, b = 0, a = 0;
};

Colour unpack(ImU32 c) {
    const auto channel = [c](int shift) { return static_cast<float>((c >> shift) & 0xFFu) / 255.0f; };
    return {channel(IM_COL32_R_SHIFT), channel(IM_COL32_G_SHIFT), channel(IM_COL32_B_SHIFT), channel(IM_COL32_A_SHIFT)};
}

// Pixels [x0, x1) x [y0, y1).
struct Box {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct Vertex {
    double x = 0, y = 0;  // pixels
    float u = 0, v = 0;
    Colour colour;
};

// Bilinear filtering as GL_LINEAR does it: texel centres at (i + 0.5) / width, the four nearest weighted by
// distance, and the edge texels repeated beyond the border (ImGui's atlas keeps a blank margin around each glyph,
// so the wrap mode never shows).
Colour sample(const Texture* texture, float u, float v) {
    if (!texture) return {1, 1, 1, 1};
    const float x = u * static_cast<float>(texture->width) - 0.5f, y = v * static_cast<float>(texture->height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const int i = static_cast<int>(fx), j = static_cast<int>(fy);
    const auto texel = [texture](int ti, int tj) {
        ti = std::clamp(ti, 0, texture->width - 1);
        tj = std::clamp(tj, 0, texture->height - 1);
        return texture->rgba + (static_cast<std::size_t>(tj) * static_cast<std::size_t>(texture->width) +
                                static_cast<std::size_t>(ti)) *
                                   4;
    };
    const unsigned char *p00 = texel(i, j), *p10 = texel(i + 1, j), *p01 = texel(i, j + 1), *p11 = texel(i + 1, j + 1);
    const auto mix = [&](int k) {
        const float top = p00[k] + (p10[k] - p00[k]) * ax, bottom = p01[k] + (p11[k] - p01[k]) * ax;
        return (top + (bottom - top) * ay) / 255.0f;
    };
    return {mix(0), mix(1), mix(2), mix(3)};
}

unsigned char to_byte(float f) {
    return static_cast<unsigned char>(std::clamp(f, 0.0f, 1.0f) * 255.0f + 0.5f);
}

// dst = src * src.a + dst * (1 - src.a) for colour, dst.a = src.a + dst.a * (1 - src.a): ImGui's blend state.
void blend(unsigned char* p, const Colour& s) {
    if (s.a <= 0.0f) return;
    const float keep = 1.0f - s.a;
    p[0] = to_byte(s.r * s.a + static_cast<float>(p[0]) / 255.0f * keep);
    p[1] = to_byte(s.g * s.a + static_cast<float>(p[1]) / 255.0f * keep);
    p[2] = to_byte(s.b * s.a + static_cast<float>(p[2]) / 255.0f * keep);
    p[3] = to_byte(s.a + static_cast<float>(p[3]) / 255.0f * keep);
}

// Twice the signed area of (a, b, p); positive when p is inside a triangle wound like (a, b, c) with c at positive
// area. Exact here: the inputs are floats, so their differences and products fit a double.
double edge(const Vertex& a, const Vertex& b, double px, double py) {
    return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

// The top-left rule: a pixel centre exactly on an edge belongs to the triangle when the edge is a top edge
// (horizontal, the triangle below it) or a left edge, so two triangles sharing an edge draw its pixels once.
// With y down and the winding above, edge a -> b is a left edge when it goes up and a top edge when it goes right.
bool owns(const Vertex& a, const Vertex& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return dy < 0.0 || (dy == 0.0 && dx > 0.0);
}

void fill_triangle(Vertex a, Vertex b, Vertex c, const Texture* texture, const Box& clip, Image& image) {
    double area = edge(a, b, c.x, c.y);
    if (!std::isfinite(area) || area == 0.0) return;
    if (area < 0.0) {
        std::swap(b, c);
        area = -area;
    }
    // Pixel x is a candidate when its centre x + 0.5 lies within the triangle's horizontal extent.
    const auto first = [](double lo) { return static_cast<int>(std::ceil(lo - 0.5)); };
    const auto past = [](double hi) { return static_cast<int>(std::floor(hi - 0.5)) + 1; };
    const int x0 = std::max(clip.x0, first(std::min({a.x, b.x, c.x})));
    const int x1 = std::min(clip.x1, past(std::max({a.x, b.x, c.x})));
    const int y0 = std::max(clip.y0, first(std::min({a.y, b.y, c.y})));
    const int y1 = std::min(clip.y1, past(std::max({a.y, b.y, c.y})));
    if (x0 >= x1 || y0 >= y1) return;

    const bool own_bc = owns(b, c), own_ca = owns(c, a), own_ab = owns(a, b);
    // Lines and fills carry one colour and the atlas's white pixel: sample once.
    const bool flat = a.u == b.u && a.u == c.u && a.v == b.v && a.v == c.v;
    const bool one_colour = a.colour.r == b.colour.r && a.colour.r == c.colour.r && a.colour.g == b.colour.g &&
                            a.colour.g == c.colour.g && a.colour.b == b.colour.b && a.colour.b == c.colour.b &&
                            a.colour.a == b.colour.a && a.colour.a == c.colour.a;
    const Colour flat_texel = flat ? sample(texture, a.u, a.v) : Colour{};
    for (int y = y0; y < y1; ++y) {
        const double py = y + 0.5;
        unsigned char* row =
            image.rgba.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) * 4;
        for (int x = x0; x < x1; ++x) {
            const double px = x + 0.5;
            const double wa = edge(b, c, px, py), wb = edge(c, a, px, py), wc = edge(a, b, px, py);
            if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
            if ((wa == 0.0 && !own_bc) || (wb == 0.0 && !own_ca) || (wc == 0.0 && !own_ab)) continue;
            // Barycentric weights: the attributes vary linearly over the triangle (the projection is orthographic).
            const float la = static_cast<float>(wa / area), lb = static_cast<float>(wb / area),
                        lc = static_cast<float>(wc / area);
            Colour vertex = a.colour;
            if (!one_colour) {
                vertex.r = la * a.colour.r + lb * b.colour.r + lc * c.colour.r;
                vertex.g = la * a.colour.g + lb * b.colour.g + lc * c.colour.g;
                vertex.b = la * a.colour.b + lb * b.colour.b + lc * c.colour.b;
                vertex.a = la * a.colour.a + lb * b.colour.a + lc * c.colour.a;
            }
            const Colour texel =
                flat ? flat_texel : sample(texture, la * a.u + lb * b.u + lc * c.u, la * a.v + lb * b.v + lc * c.v);
            blend(row + static_cast<std::size_t>(x) * 4,
                  {vertex.r * texel.r, vertex.g * texel.g, vertex.b * texel.b, vertex.a * texel.a});
        }
    }
}

// glScissor's box for a clip rectangle, as ImGui's OpenGL backend sets it (GL counts rows from the bottom and
// truncates to whole pixels), in rows from the top.
Box scissor(const ImVec4& clip, const ImDrawData& data, const Image& image) {
    const ImVec2 scale = data.FramebufferScale.x > 0 ? data.FramebufferScale : ImVec2(1, 1);
    const float min_x = (clip.x - data.DisplayPos.x) * scale.x, min_y = (clip.y - data.DisplayPos.y) * scale.y;
    const float max_x = (clip.z - data.DisplayPos.x) * scale.x, max_y = (clip.w - data.DisplayPos.y) * scale.y;
    if (max_x <= min_x || max_y <= min_y) return {};
    const int x = static_cast<int>(min_x), w = static_cast<int>(max_x - min_x);
    const int gl_y = static_cast<int>(static_cast<float>(image.height) - max_y), h = static_cast<int>(max_y - min_y);
    Box box{x, image.height - (gl_y + h), x + w, image.height - gl_y};
    box.x0 = std::max(box.x0, 0);
    box.y0 = std::max(box.y0, 0);
    box.x1 = std::min(box.x1, image.width);
    box.y1 = std::min(box.y1, image.height);
    return box;
}

}  // namespace

Image::Image(int width_, int height_, ImU32 fill) : width(width_), height(height_) {
    rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    const unsigned char channels[4] = {
        static_cast<unsigned char>(fill >> IM_COL32_R_SHIFT), static_cast<unsigned char>(fill >> IM_COL32_G_SHIFT),
        static_cast<unsigned char>(fill >> IM_COL32_B_SHIFT), static_cast<unsigned char>(fill >> IM_COL32_A_SHIFT)};
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = channels[i % 4];
}

ImU32 Image::at(int x, int y) const {
    const unsigned char* p =
        rgba.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
    return IM_COL32(p[0], p[1], p[2], p[3]);
}

void rasterize(const ImDrawData& data, Image& image) {
    const ImVec2 scale = data.FramebufferScale.x > 0 ? data.FramebufferScale : ImVec2(1, 1);
    for (int l = 0; l < data.CmdListsCount; ++l) {
        const ImDrawList& list = *data.CmdLists[l];
        for (const ImDrawCmd& command : list.CmdBuffer) {
            if (command.UserCallback || command.ElemCount == 0) continue;
            const Box clip = scissor(command.ClipRect, data, image);
            if (clip.x0 >= clip.x1 || clip.y0 >= clip.y1) continue;
            const auto* texture = static_cast<const Texture*>(command.GetTexID());
            const auto vertex = [&](unsigned int index) {
                const ImDrawVert& v = list.VtxBuffer[static_cast<int>(command.VtxOffset + index)];
                return Vertex{(v.pos.x - data.DisplayPos.x) * scale.x, (v.pos.y - data.DisplayPos.y) * scale.y, v.uv.x,
                              v.uv.y, unpack(v.col)};
            };
            for (unsigned int i = 0; i + 2 < command.ElemCount; i += 3) {
                const ImDrawIdx* index = list.IdxBuffer.Data + command.IdxOffset + i;
                fill_triangle(vertex(index[0]), vertex(index[1]), vertex(index[2]), texture, clip, image);
            }
        }
    }
}

std::string png_bytes(const Image& image) {
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    stbi_write_png_compression_level = 6;
    stbi_write_force_png_filter = 0;  // about three times faster than trying every filter, a little larger
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
        return {};
    return bytes;
}

}  // namespace impulse::bench
