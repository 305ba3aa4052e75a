#pragma once
// The bench's pictures, drawn with Dear ImGui draw lists on a canvas that needs no display (bench/chart_canvas):
// speed against accuracy (one log-log panel per scene, one series per method, the Pareto front marked) and
// the stability matrix (methods x stress scenes: green meets the target, amber holds but misses it, red fails).

#include "bench/bench_report.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impulse::bench {

// A place on a chart, in pixels (y down).
struct ChartPoint {
    float x = 0.0f;
    float y = 0.0f;
};

// Where to draw markers so that none hides another: in order, each at its data's place when no marker drawn
// before it is nearer than `apart`, else at the first free place of: sideways 1 to 4 widths (right, then left),
// then the diagonals and straight up or down 1 to 3 widths, inside [lo, hi]. On the log axes sideways changes
// the time shown far less than up or down changes the error. A marker with no free place keeps its own.
std::vector<ChartPoint> dodged_markers(const std::vector<ChartPoint>& at, float apart, ChartPoint lo, ChartPoint hi);

// A box on a chart: its left, top, right and bottom, in pixels.
struct ChartBox {
    float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
    bool overlaps(const ChartBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// Where to put each marker's label (`sizes[i]` wide and high) so that no label covers another, a marker or
// anything in `taken` (other text), inside `bounds`: in order, the first free place on rings of growing distance
// round its marker (beside it first, then above, below and the diagonals, then farther out, where the chart draws
// a thin line back to the marker). A label with no free place is left out (none): better no label than one on top
// of another.
std::vector<std::optional<ChartPoint>> placed_labels(const std::vector<ChartPoint>& markers,
                                                     const std::vector<ChartPoint>& sizes, std::vector<ChartBox> taken,
                                                     ChartBox bounds);

// PNG bytes. Throw ChartError (bench/chart_canvas.hpp) when the picture cannot be encoded.
std::string speed_accuracy_png(const bench::BenchRun& run);
std::string stability_png(const bench::BenchRun& run);

}  // namespace impulse::bench
