// The bench's software renderer of ImGui draw data, on draw lists written by hand (no ImGui context): which
// pixels a triangle covers, how scissors clip, how colours blend and interpolate, and how textures are sampled.
// The expected values are worked out by hand in each test's comment.

#include "bench/draw_data_raster.hpp"

#include <doctest/doctest.h>

#include <vector>

namespace impulse::test {

namespace {

using bench::Image;
using bench::Texture;

constexpr ImU32 white = IM_COL32(255, 255, 255, 255);
constexpr ImU32 black = IM_COL32(0, 0, 0, 255);

// One draw list filled by hand: each `command` call adds a draw command over the vertices given so far.
struct HandList {
    ImDrawList list{nullptr};

    HandList() { list.CmdBuffer.clear(); }
    void vertex(float x, float y, ImU32 colour, float u = 0, float v = 0) {
        list.VtxBuffer.push_back(ImDrawVert{{x, y}, {u, v}, colour});
    }
    // A quad (x0, y0)-(x1, y1) as two triangles sharing the diagonal from top left to bottom right.
    void quad(float x0, float y0, float x1, float y1, ImU32 colour) {
        const auto first = static_cast<ImDrawIdx>(list.VtxBuffer.Size);
        vertex(x0, y0, colour);
        vertex(x1, y0, colour);
        vertex(x1, y1, colour);
        vertex(x0, y1, colour);
        for (const int i : {0, 1, 2, 0, 2, 3}) list.IdxBuffer.push_back(static_cast<ImDrawIdx>(first + i));
    }
    void command(ImVec4 clip, const Texture* texture = nullptr, unsigned vertex_offset = 0) {
        unsigned drawn = 0;
        for (const ImDrawCmd& c : list.CmdBuffer) drawn += c.ElemCount;
        ImDrawCmd c;
        c.ClipRect = clip;
        c.TextureId = const_cast<Texture*>(texture);
        c.VtxOffset = vertex_offset;
        c.IdxOffset = drawn;
        c.ElemCount = static_cast<unsigned>(list.IdxBuffer.Size) - drawn;
        list.CmdBuffer.push_back(c);
    }
    Image draw(int width, int height, ImU32 background) {
        Image image(width, height, background);
        ImDrawList* lists[] = {&list};
        ImDrawData data;
        data.Valid = true;
        data.CmdListsCount = 1;
        data.CmdLists = lists;
        data.DisplaySize = {static_cast<float>(width), static_cast<float>(height)};
        data.FramebufferScale = {1, 1};
        bench::rasterize(data, image);
        return image;
    }
};

const ImVec4 everywhere{0, 0, 1000, 1000};

unsigned green(ImU32 c) {
    return (c >> IM_COL32_G_SHIFT) & 0xFF;
}

}  // namespace

TEST_CASE("a quad covers exactly the pixels whose centres lie inside it, its shared diagonal drawn once") {
    // The quad (1, 1)-(5, 5) holds the centres x + 0.5 for x = 1..4, so 4 x 4 pixels. Half-transparent red
    // (alpha 128) over white leaves green at 255 (1 - 128/255) = 127 where drawn once, 63 where drawn twice: the
    // two triangles share the diagonal, whose pixel centres (1.5, 1.5), ... lie on both.
    HandList hand;
    hand.quad(1, 1, 5, 5, IM_COL32(255, 0, 0, 128));
    hand.command(everywhere);
    const Image image = hand.draw(8, 8, white);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool inside = x >= 1 && x <= 4 && y >= 1 && y <= 4;
            CAPTURE(x);
            CAPTURE(y);
            CHECK(image.at(x, y) == (inside ? IM_COL32(255, 127, 127, 255) : white));
        }
}

TEST_CASE("a pixel centre on a top or left edge is drawn and one on a bottom or right edge is not") {
    // The quad (0.5, 0.5)-(2.5, 2.5) passes through pixel centres on all four sides. The top-left rule keeps
    // the centres on x = 0.5 and y = 0.5 and drops those on x = 2.5 and y = 2.5: pixels x, y in {0, 1}.
    HandList hand;
    hand.quad(0.5f, 0.5f, 2.5f, 2.5f, IM_COL32(255, 0, 0, 128));
    hand.command(everywhere);
    const Image image = hand.draw(4, 4, white);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            CAPTURE(x);
            CAPTURE(y);
            CHECK(green(image.at(x, y)) == (x <= 1 && y <= 1 ? 127u : 255u));
        }
}

TEST_CASE("a command's clip rectangle cuts what it draws to whole pixels inside it") {
    // Black over the whole 8 x 8 image, clipped to (2, 3)-(6, 5): pixels x = 2..5, y = 3..4 only.
    HandList hand;
    hand.quad(0, 0, 8, 8, black);
    hand.command({2, 3, 6, 5});
    const Image image = hand.draw(8, 8, white);
    int drawn = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            if (image.at(x, y) == black) {
                ++drawn;
                CHECK((x >= 2 && x <= 5 && y >= 3 && y <= 4));
            }
    CHECK(drawn == 8);
}

TEST_CASE("colours blend over what is drawn: source by its alpha, the rest by one minus it") {
    // Blue at alpha 64 over opaque red: a = 64/255 = 0.251, red 255 (1 - a) = 191.0, blue 255 a = 64, alpha
    // a + 1 (1 - a) = 255. Then the same blue again: red 191.0 (1 - a) = 143.1 -> 143, blue 64 + 64 (1 - a) =
    // 111.9 -> 112.
    HandList hand;
    hand.quad(0, 0, 1, 1, IM_COL32(0, 0, 255, 64));
    hand.quad(1, 0, 2, 1, IM_COL32(0, 0, 255, 64));
    hand.quad(1, 0, 2, 1, IM_COL32(0, 0, 255, 64));
    hand.command(everywhere);
    const Image image = hand.draw(2, 1, IM_COL32(255, 0, 0, 255));
    CHECK(image.at(0, 0) == IM_COL32(191, 0, 64, 255));
    CHECK(image.at(1, 0) == IM_COL32(143, 0, 112, 255));
}

TEST_CASE("a colour that differs at each vertex is interpolated to each pixel centre") {
    // Black at x = 0, white at x = 4, over a 4 x 1 quad: pixel centres x + 0.5 get 255 (x + 0.5) / 4 =
    // 31.9, 95.6, 159.4, 223.1 -> 32, 96, 159, 223.
    HandList hand;
    hand.vertex(0, 0, black);
    hand.vertex(4, 0, white);
    hand.vertex(4, 1, white);
    hand.vertex(0, 1, black);
    for (const int i : {0, 1, 2, 0, 2, 3}) hand.list.IdxBuffer.push_back(static_cast<ImDrawIdx>(i));
    hand.command(everywhere);
    const Image image = hand.draw(4, 1, IM_COL32(255, 0, 0, 255));
    CHECK(green(image.at(0, 0)) == 32);
    CHECK(green(image.at(1, 0)) == 96);
    CHECK(green(image.at(2, 0)) == 159);
    CHECK(green(image.at(3, 0)) == 223);
}

TEST_CASE("a textured quad takes the texel under each pixel centre, and a stretched one blends the nearest two") {
    // A glyph-like texture, 4 x 1, white with alpha 0, 255, 255, 0, times an opaque black vertex colour.
    const unsigned char texels[] = {255, 255, 255, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0};
    const Texture texture{4, 1, texels};
    HandList hand;
    // 1:1 over pixels (0, 0)-(4, 1): each centre falls on a texel centre, so white, black, black, white.
    hand.vertex(0, 0, black, 0, 0);
    hand.vertex(4, 0, black, 1, 0);
    hand.vertex(4, 1, black, 1, 1);
    hand.vertex(0, 1, black, 0, 1);
    // Stretched twice over (0, 1)-(8, 2): pixel x's centre is at texel coordinate (x + 0.5) / 2 - 0.5, so
    // x = 1 lies a quarter of the way from texel 0 to texel 1: alpha 0.25, white 255 (1 - 0.25) = 191.25 -> 191;
    // x = 2, 0.75 of the way: 255 (1 - 0.75) = 63.75 -> 64; x = 0 is before texel 0's centre and takes it: 255.
    hand.vertex(0, 1, black, 0, 0);
    hand.vertex(8, 1, black, 1, 0);
    hand.vertex(8, 2, black, 1, 1);
    hand.vertex(0, 2, black, 0, 1);
    for (const int i : {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7}) hand.list.IdxBuffer.push_back(static_cast<ImDrawIdx>(i));
    hand.command(everywhere, &texture);
    const Image image = hand.draw(8, 2, white);
    CHECK(image.at(0, 0) == white);
    CHECK(image.at(1, 0) == black);
    CHECK(image.at(2, 0) == black);
    CHECK(image.at(3, 0) == white);
    CHECK(image.at(4, 0) == white);  // past the 1:1 quad
    CHECK(green(image.at(0, 1)) == 255);
    CHECK(green(image.at(1, 1)) == 191);
    CHECK(green(image.at(2, 1)) == 64);
    CHECK(green(image.at(3, 1)) == 0);
}

TEST_CASE("a command's vertex offset picks its vertices, as for draw lists past 65536 vertices") {
    // Two quads; one command whose indices 0..3 start at vertex 4 draws the second one, (2, 0)-(3, 1), only.
    HandList hand;
    hand.quad(0, 0, 1, 1, black);
    hand.quad(2, 0, 3, 1, black);
    hand.list.IdxBuffer.resize(6);  // the first quad's indices, 0..3, serve the second through the offset
    hand.command(everywhere, nullptr, 4);
    const Image image = hand.draw(4, 1, white);
    CHECK(image.at(0, 0) == white);
    CHECK(image.at(2, 0) == black);
}

}  // namespace impulse::test
