#include "gui/visible_text.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

namespace impulse::gui {

namespace {

struct GlyphRef {
    const ImFont* font;
    const ImFontGlyph* glyph;
};

}  // namespace

// Which glyph covers each texel of the font atlas (glyphs never overlap there): the centre of a glyph quad's
// texture rectangle names its glyph even when ImGui clipped the quad, and a filled shape's white texel none.
class AtlasIndex {
public:
    explicit AtlasIndex(const ImFontAtlas& atlas) : width_(atlas.TexWidth), height_(atlas.TexHeight) {
        texels_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), -1);
        for (const ImFont* font : atlas.Fonts)
            for (const ImFontGlyph& g : font->Glyphs) {
                if (!g.Visible) continue;
                const int x0 = static_cast<int>(std::floor(g.U0 * width_)),
                          x1 = static_cast<int>(std::ceil(g.U1 * width_));
                const int y0 = static_cast<int>(std::floor(g.V0 * height_)),
                          y1 = static_cast<int>(std::ceil(g.V1 * height_));
                const auto index = static_cast<std::int32_t>(glyphs_.size());
                glyphs_.push_back({font, &g});
                for (int y = std::max(y0, 0); y < std::min(y1, height_); ++y)
                    for (int x = std::max(x0, 0); x < std::min(x1, width_); ++x)
                        texels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                                static_cast<std::size_t>(x)] = index;
            }
    }
    const GlyphRef* at(float u, float v) const {
        const int x = static_cast<int>(u * static_cast<float>(width_)),
                  y = static_cast<int>(v * static_cast<float>(height_));
        if (x < 0 || y < 0 || x >= width_ || y >= height_) return nullptr;
        const std::int32_t i =
            texels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)];
        return i < 0 ? nullptr : &glyphs_[static_cast<std::size_t>(i)];
    }

private:
    int width_, height_;
    std::vector<std::int32_t> texels_;
    std::vector<GlyphRef> glyphs_;
};

namespace {

struct Placed {
    std::size_t order;  // as drawn: a combining mark comes after its letter at the same x
    float x, y;         // the glyph's pen position: its line's top left, as RenderText placed it
    float advance;
    float space;  // the width of a space in its font: a gap of about one is a space, a wider one a new run
    unsigned codepoint;
};

void append_utf8(std::string& text, unsigned c) {
    if (c < 0x80) {
        text += static_cast<char>(c);
    } else if (c < 0x800) {
        text += static_cast<char>(0xC0 | (c >> 6));
        text += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        text += static_cast<char>(0xE0 | (c >> 12));
        text += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        text += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        text += static_cast<char>(0xF0 | (c >> 18));
        text += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        text += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        text += static_cast<char>(0x80 | (c & 0x3F));
    }
}

}  // namespace

TextReader::TextReader(const ImFontAtlas& atlas) : index_(std::make_unique<AtlasIndex>(atlas)) {}

TextReader::~TextReader() = default;

std::vector<VisibleRun> TextReader::read(const ImDrawData& drawn) const {
    const AtlasIndex* index = index_.get();
    std::vector<VisibleRun> runs;
    for (int l = 0; l < drawn.CmdListsCount; ++l) {
        const ImDrawList& list = *drawn.CmdLists[l];
        std::vector<Placed> placed;
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            if (cmd.UserCallback) continue;
            const ImDrawIdx* idx = list.IdxBuffer.Data + cmd.IdxOffset;
            const ImDrawVert* vtx = list.VtxBuffer.Data + cmd.VtxOffset;
            // Every primitive is triangles (three indices each); a glyph is a quad, two of them, as ImFont::RenderText
            // writes one: (a, a+1, a+2) (a, a+2, a+3). A lone triangle (a combo's arrow) shifts what follows by three.
            for (unsigned int i = 0; i + 6 <= cmd.ElemCount; i += 3) {
                const ImDrawIdx* q = idx + i;
                if (q[3] != q[0] || q[4] != q[2] || q[1] != q[0] + 1 || q[2] != q[0] + 2 || q[5] != q[0] + 3) continue;
                const ImDrawVert& top_left = vtx[q[0]];
                const ImDrawVert& bottom_right = vtx[q[2]];
                if (top_left.uv.x == bottom_right.uv.x || top_left.uv.y == bottom_right.uv.y) continue;
                const GlyphRef* g =
                    index->at((top_left.uv.x + bottom_right.uv.x) / 2, (top_left.uv.y + bottom_right.uv.y) / 2);
                if (!g) continue;
                const float cx = (top_left.pos.x + bottom_right.pos.x) / 2,
                            cy = (top_left.pos.y + bottom_right.pos.y) / 2;
                if (cx < cmd.ClipRect.x || cx > cmd.ClipRect.z || cy < cmd.ClipRect.y || cy > cmd.ClipRect.w) continue;
                const float scale = 1.0f;  // fonts are drawn at their loaded size
                // The pen position: the quad's corner less the glyph's offset (exact unless the quad was clipped).
                const float u_share = (top_left.uv.x - g->glyph->U0) / (g->glyph->U1 - g->glyph->U0);
                const float v_share = (top_left.uv.y - g->glyph->V0) / (g->glyph->V1 - g->glyph->V0);
                const float x = top_left.pos.x - (g->glyph->X0 + u_share * (g->glyph->X1 - g->glyph->X0)) * scale;
                const float y = top_left.pos.y - (g->glyph->Y0 + v_share * (g->glyph->Y1 - g->glyph->Y0)) * scale;
                const ImFontGlyph* space = g->font->FindGlyphNoFallback(' ');
                placed.push_back({placed.size(), x, y, g->glyph->AdvanceX * scale,
                                  (space ? space->AdvanceX : 0.3f * g->font->FontSize) * scale, g->glyph->Codepoint});
                i += 3;  // the quad's second triangle
            }
        }
        // Lines (glyphs whose pen stands at the same height), then left to right.
        std::stable_sort(placed.begin(), placed.end(), [](const Placed& a, const Placed& b) {
            if (std::abs(a.y - b.y) > 0.5f) return a.y < b.y;
            if (a.x != b.x) return a.x < b.x;
            return a.order < b.order;
        });
        VisibleRun run;
        float end = 0, line = -1e9f;
        for (const Placed& p : placed) {
            const float gap = p.x - end;
            // A gap wider than a space and a half starts another run (a table cell, another label); about one
            // space is a space between words.
            if (std::abs(p.y - line) > 0.5f || gap > 1.6f * p.space || gap < -1.5f * p.space) {
                if (!run.text.empty()) runs.push_back(run);
                run = VisibleRun{list._OwnerName ? list._OwnerName : "", {}, p.x, p.y};
                line = p.y;
                end = p.x;
            } else if (gap > 0.5f * p.space) {
                run.text += ' ';
            }
            append_utf8(run.text, p.codepoint);
            end = std::max(end, p.x + p.advance);
            if (p.advance == 0.0f) end = std::max(end, p.x);
        }
        if (!run.text.empty()) runs.push_back(run);
    }
    return runs;
}

}  // namespace impulse::gui
