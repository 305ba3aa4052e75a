#pragma once
// The bench's pictures, drawn with Dear ImGui draw lists into the headless display and encoded as PNG:
// speed against accuracy (one log-log panel per scene, one series per method, the Pareto front marked) and
// the stability matrix (methods x stress scenes: green meets the target, amber holds but misses it, red fails).

#include "bench/bench_report.hpp"

#include <string>
#include <vector>

namespace impulse::gui {

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

// PNG bytes. Throw DisplayError when no offscreen display can be opened.
std::string speed_accuracy_png(const bench::BenchRun& run);
std::string stability_png(const bench::BenchRun& run);

}  // namespace impulse::gui
