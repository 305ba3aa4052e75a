#include "bench/bench_runs.hpp"

#include "formats/scene_file.hpp"
#include "record/trace_recorder.hpp"
#include "world/world.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

namespace impulse::bench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Steps `frames` frames of a copy of `start` (the world as the window begins: its bodies, its contact memory,
// its frame) and returns each frame's step time; `recorder` sees every frame. With a trace recorder the
// recorded frames are dropped after each step (outside the timing), so memory stays flat.
std::vector<double> time_window(const World& start, int frames, Recorder& recorder, Trace* trace) {
    World world = start;
    std::vector<double> times;
    times.reserve(static_cast<std::size_t>(frames));
    for (int frame = 0; frame < frames; ++frame) {
        const auto begin = Clock::now();
        if (world.step(recorder).over_contact_budget) throw formats::contact_budget_error(world.frame());
        times.push_back(seconds_since(begin));
        if (trace) trace->frames.clear();
    }
    return times;
}

}  // namespace

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

int frames_for(const BenchScene& spec, const Timing& timing) {
    return timing.frames.value_or(spec.frames);
}

int warm_up_for(int frames, const Timing& timing) {
    return std::min(timing.warm_up, frames / 4);
}

int window_for(int frames, const Timing& timing) {
    // At most half the frames after the warm-up, so the repeats cost no more than the accuracy run.
    return std::max(1, std::min(timing.window, (frames - warm_up_for(frames, timing)) / 2));
}

RunResult run_configuration(const std::string& scene_text, const BenchScene& spec, std::string_view method, int n,
                            const Timing& timing) {
    if (const EngineRow* engine = find_engine(method))
        return run_engine_configuration(formats::read_scene_text(scene_text), spec, *engine, n, timing);
    Scene scene = formats::read_scene_text(scene_text, std::string(method));
    set_iteration_count(scene.settings, n);
    RunResult result;
    result.scene = spec.name;
    result.method = std::string(method);
    result.n = n;
    result.iteration_setting = std::string(iteration_setting(scene.settings));
    result.duration = scene.settings.duration;
    const int frames = frames_for(spec, timing);
    const int warm_up = warm_up_for(frames, timing);
    const int window = window_for(frames, timing);

    // The accuracy run, whose frames [warm_up, warm_up + window) are the first timed window.
    AccuracyTracker tracker(scene, spec, frames);
    World world(scene);
    std::optional<World> start;  // the world as the timed window begins
    Recorder nobody;
    std::vector<double> times;
    long contacts = 0;
    int frame = 0;
    for (; frame < frames; ++frame) {
        if (frame == warm_up) start = world;
        const auto begin = Clock::now();
        const StepReport report = world.step(nobody);
        const double elapsed = seconds_since(begin);
        if (report.over_contact_budget) throw formats::contact_budget_error(frame);
        if (frame >= warm_up && frame < warm_up + window) times.push_back(elapsed);
        contacts += report.contacts;
        if (!tracker.observe(frame, world.bodies(), report)) {
            ++frame;
            break;
        }
    }
    result.frames = frame;
    result.contacts_per_frame = frame > 0 ? static_cast<double>(contacts) / frame : 0.0;
    result.accuracy = tracker.finish(world.bodies());
    const bool whole_window = frame >= warm_up + window;

    // Further repeats of the window, when the first one was whole (a run that became NaN is timed once).
    if (whole_window)
        for (int r = 1; r < timing.repeats; ++r) {
            const std::vector<double> more = time_window(*start, window, nobody, nullptr);
            times.insert(times.end(), more.begin(), more.end());
        }
    result.time_per_step = median(times);
    result.timed_frames = static_cast<int>(times.size());

    if (timing.measure_recording && whole_window) {
        std::vector<double> recorded;
        for (int r = 0; r < timing.repeats; ++r) {
            Trace trace;
            trace.scene.settings = scene.settings;  // the recorder reads the phase order from the header
            TraceRecorder recorder(trace);
            const std::vector<double> more = time_window(*start, window, recorder, &trace);
            recorded.insert(recorded.end(), more.begin(), more.end());
        }
        if (result.time_per_step > 0.0) result.recording_ratio = median(recorded) / result.time_per_step;
    }
    return result;
}

}  // namespace impulse::bench
