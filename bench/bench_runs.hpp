#pragma once
// One configuration of the bench (a scene, a method, an iteration count) run once for its accuracy and
// timed: every frame's step is timed, the time per step is the median over a window of frames after a
// warm-up, and further repeats re-run that window from a snapshot of the state at its start.

#include "bench/adapters/engine_adapter.hpp"
#include "bench/bench_metrics.hpp"
#include "bench/bench_plan.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::bench {

struct Timing {
    int repeats = 3;                 // timed windows (the first is part of the accuracy run)
    int warm_up = 10;                // frames stepped before the window
    int window = 60;                 // frames per timed window
    std::optional<int> frames;       // overrides every scene's simulated frames
    bool measure_recording = false;  // also time the window with a TraceRecorder on
};

struct RunResult {
    std::string scene;
    std::string method;
    int n = 0;                      // the iteration count
    std::string iteration_setting;  // what N set ("iterations_per_contact", "sweeps", "soft_step.substeps")
    int frames = 0;                 // frames simulated (fewer when the run became NaN)
    double duration = 0.0;          // s per frame
    double contacts_per_frame = 0.0;
    double time_per_step = 0.0;             // s: median step time over the timed windows
    int timed_frames = 0;                   // step times the median was taken over
    std::optional<double> recording_ratio;  // median step time with a TraceRecorder on / off
    Accuracy accuracy;
};

// Frames the bench simulates for `spec` (its own, or the override), and the window within them.
int frames_for(const BenchScene& spec, const Timing& timing);
int warm_up_for(int frames, const Timing& timing);
int window_for(int frames, const Timing& timing);

// `scene_text` is the scene file's text; `method` a preset name or an engine's (then run_engine_configuration).
// Throws formats::InputError for a bad file.
RunResult run_configuration(const std::string& scene_text, const BenchScene& spec, std::string_view method, int n,
                            const Timing& timing);

// The same for another engine (bench/adapters): `scene` as read from the file. Timing covers the engine's step
// only; each further repeat rebuilds the engine's world and steps it untimed to the window.
RunResult run_engine_configuration(const Scene& scene, const BenchScene& spec, const EngineRow& engine, int n,
                                   const Timing& timing);

// Median of the values (the upper one of an even count); 0 for none.
double median(std::vector<double> values);

}  // namespace impulse::bench
