// The bench's charts drawn with no display: the canvas's text samples the font atlas, and hand-made runs come
// out as pictures of their data. These tests link the bench library alone, without SDL2 or OpenGL.

#include "bench/bench_charts.hpp"
#include "bench/bench_plan.hpp"
#include "bench/chart_canvas.hpp"
#include "support/bench_scenes.hpp"
#include "support/png_image.hpp"

#include <doctest/doctest.h>

#include <algorithm>

namespace impulse::test {

namespace {

bench::RunResult row(const std::string& method, int n, double ms, double error, bool meets, bool holds = true) {
    bench::RunResult r;
    r.scene = "stack_10";
    r.method = method;
    r.n = n;
    r.time_per_step = ms * 1e-3;
    r.accuracy.error = error;
    r.accuracy.meets_target = meets;
    r.accuracy.holds = holds;
    if (!holds) {
        r.accuracy.failure = "collapsed";
        r.accuracy.failure_time = 2.5;
    }
    return r;
}

std::size_t pixels_of(const PngImage& image, unsigned rgb) {
    std::size_t n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += image.at(x, y) == rgb ? 1 : 0;
    return n;
}

// Pixels with every channel at most 60: text in ink (30, 30, 30) and its antialiased edges, as nothing else on
// the charts is that dark (the faint grey is 120, the dashed line 90, the method colours have a channel over 150).
std::size_t dark_pixels(const PngImage& image) {
    std::size_t n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const unsigned c = image.at(x, y);
            n += (c >> 16) <= 60 && ((c >> 8) & 0xFF) <= 60 && (c & 0xFF) <= 60 ? 1 : 0;
        }
    return n;
}

}  // namespace

TEST_CASE("text on the chart canvas is the font atlas's glyphs: strokes of ink inside the text's box, white outside") {
    // "HIH" in black at (10, 10), 15 px (the atlas's own size). DejaVu's capitals are 0.73 em = 11 px tall and
    // their stems 0.1 em = 1.5 px wide, so each of the five stems is at least half ink over one pixel in each of
    // its 11 rows: 55 pixels darker than mid grey, at least, and a stem wider than a pixel leaves some nearly
    // black. Nothing is drawn outside the box the font measures (its advance x 15 px) but a pixel of fringe.
    float width = 0;
    const PngImage image = png_from_bytes(bench::draw_png(80, 40, [&width](ImDrawList& list) {
        list.AddText(ImGui::GetFont(), 15.0f, {10, 10}, IM_COL32(0, 0, 0, 255), "HIH");
        width = ImGui::GetFont()->CalcTextSizeA(15.0f, 1e9f, 0.0f, "HIH").x;
    }));
    REQUIRE(width > 20);
    CHECK(image.width == 80);
    CHECK(image.height == 40);
    std::size_t half_ink = 0;
    unsigned darkest = 255;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const unsigned grey = image.at(x, y) & 0xFF;
            const bool inside = x >= 9 && x <= 10 + static_cast<int>(width) + 1 && y >= 9 && y <= 26;
            if (!inside) {
                CAPTURE(x);
                CAPTURE(y);
                CHECK(image.at(x, y) == 0xFFFFFFu);
            }
            half_ink += grey < 128 ? 1 : 0;
            darkest = std::min(darkest, grey);
        }
    CHECK(half_ink >= 55);
    CHECK(darkest < 32);
}

TEST_CASE("the chart canvas leaves the caller's ImGui context current") {
    ImGuiContext* caller = ImGui::CreateContext();
    ImGuiContext* during = nullptr;
    bench::draw_png(4, 4, [&during](ImDrawList&) { during = ImGui::GetCurrentContext(); });
    CHECK(during != nullptr);
    CHECK(during != caller);
    CHECK(ImGui::GetCurrentContext() == caller);
    ImGui::DestroyContext(caller);
}

TEST_CASE("a hand-made run's charts show each method's markers in its colour and each verdict in its fill") {
    // stack_10 (top_drift, target 0.05 m), book at N = 4 and 8 (0.2 m, then 0.01 m: misses, then meets) and pgs
    // at N = 4 and 8 (collapsed at N = 8). One scene: one panel, 960 x 500. The matrix judges each method at its
    // largest N: book meets the target (green fill 198, 236, 198), pgs fails (red fill 248, 196, 196).
    bench::BenchRun run;
    run.scenes = {bench_scene("stack_10")};
    run.methods = {"book", "pgs"};
    run.iterations = {4, 8};
    run.rows = {row("book", 4, 0.5, 0.2, false), row("book", 8, 0.9, 0.01, true), row("pgs", 4, 0.2, 0.03, true),
                row("pgs", 8, 0.3, 5.0, false, false)};

    const PngImage chart = png_from_bytes(bench::speed_accuracy_png(run));
    CHECK(chart.width == 960);
    CHECK(chart.height == 500);
    CHECK(chart.at(0, 0) == 0xFFFFFFu);
    // book's filled circles (about 9 x 9 solid pixels each) and pgs's filled square (11 x 11) in the legend and the
    // panel; pgs's collapsed run is a hollow square.
    CHECK(pixels_of(chart, 0x0072B2u) > 3 * 50);
    CHECK(pixels_of(chart, 0xE69F00u) > 2 * 80);
    CHECK(dark_pixels(chart) > 500);  // the text in ink (30, 30, 30): three header lines, labels, the legend

    const PngImage matrix = png_from_bytes(bench::stability_png(run));
    CHECK(matrix.width == 240 + 2 * 282 + 20);
    CHECK(matrix.height == 86 + 72 + 44);
    CHECK(pixels_of(matrix, 0xC6ECC6u) > 200 * 50);  // a 278 x 68 cell less its text
    CHECK(pixels_of(matrix, 0xF8C4C4u) > 200 * 50);
}

}  // namespace impulse::test

TEST_CASE("the chart's labels never cover one another, a marker or other text, even where the markers crowd") {
    using impulse::bench::ChartBox;
    using impulse::bench::ChartPoint;
    // Twelve markers in a tight cluster (the six methods at two counts, all near one error), a target label
    // across them, and a lone marker far off.
    std::vector<ChartPoint> markers, sizes;
    for (int i = 0; i < 12; ++i) {
        markers.push_back({200.0f + 6.0f * static_cast<float>(i % 4), 150.0f + 5.0f * static_cast<float>(i / 4)});
        sizes.push_back({i % 2 ? 16.0f : 8.0f, 14.0f});
    }
    markers.push_back({380, 60});
    sizes.push_back({16, 14});
    std::vector<ChartBox> taken{{150, 135, 260, 150}};  // "target 0.02 m"
    for (const ChartPoint& m : markers) taken.push_back({m.x - 7, m.y - 7, m.x + 7, m.y + 7});
    const ChartBox bounds{60, 40, 400, 300};
    const auto labels = impulse::bench::placed_labels(markers, sizes, taken, bounds);
    REQUIRE(labels.size() == markers.size());
    std::vector<ChartBox> drawn;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        if (!labels[i]) continue;
        const ChartBox box{labels[i]->x, labels[i]->y, labels[i]->x + sizes[i].x, labels[i]->y + sizes[i].y};
        CHECK(box.x0 >= bounds.x0);
        CHECK(box.y0 >= bounds.y0);
        CHECK(box.x1 <= bounds.x1);
        CHECK(box.y1 <= bounds.y1);
        for (const ChartBox& other : taken) CHECK_FALSE(box.overlaps(other));
        for (const ChartBox& other : drawn) CHECK_FALSE(box.overlaps(other));
        drawn.push_back(box);
    }
    CHECK(drawn.size() >= 11);  // crowded, but labelled: at most one left out
    CHECK(labels.back().has_value());
}
