#pragma once
// The bench's pictures, drawn with Dear ImGui draw lists into the headless display and encoded as PNG:
// speed against accuracy (one log-log panel per scene, one series per method, the Pareto front marked) and
// the stability matrix (methods x stress scenes, green holds, red fails).

#include "bench/bench_report.hpp"

#include <string>

namespace impulse::gui {

// PNG bytes. Throw DisplayError when no offscreen display can be opened.
std::string speed_accuracy_png(const bench::BenchRun& run);
std::string stability_png(const bench::BenchRun& run);

}  // namespace impulse::gui
