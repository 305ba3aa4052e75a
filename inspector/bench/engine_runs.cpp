// A configuration run by another engine (bench/adapters): the same accuracy run, metrics and timing as ours
// (bench_runs.cpp), with the engine's step in place of ours.

#include "bench/bench_runs.hpp"

#include <chrono>

namespace impulse::bench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

RunResult run_engine_configuration(const Scene& scene, const BenchScene& spec, const EngineRow& engine, int n,
                                   const Timing& timing) {
    RunResult result;
    result.scene = spec.name;
    result.method = std::string(engine.name);
    result.n = n;
    result.iteration_setting = std::string(engine.iteration_setting);
    result.duration = scene.settings.duration;
    const int frames = frames_for(spec, timing);
    const int warm_up = warm_up_for(frames, timing);
    const int window = window_for(frames, timing);

    // The accuracy run, whose frames [warm_up, warm_up + window) are the first timed window. Only the engine's
    // step is timed; handing the bodies back is ours.
    AccuracyTracker tracker(scene, spec, frames);
    std::unique_ptr<EngineWorld> world = engine.make(scene, n);
    std::vector<RigidBody> bodies = scene.bodies;
    std::vector<double> times;
    long contacts = 0;
    int frame = 0;
    for (; frame < frames; ++frame) {
        const auto begin = Clock::now();
        world->step();
        const double elapsed = seconds_since(begin);
        if (frame >= warm_up && frame < warm_up + window) times.push_back(elapsed);
        world->read_bodies(bodies);
        StepReport report;
        report.frame = frame;
        report.contacts = world->touching_contacts();
        contacts += report.contacts;
        if (!tracker.observe(frame, bodies, report)) {
            ++frame;
            break;
        }
    }
    result.frames = frame;
    result.contacts_per_frame = frame > 0 ? static_cast<double>(contacts) / frame : 0.0;
    result.accuracy = tracker.finish(bodies);

    // Further repeats of the window. An engine's state (its contact caches, warm starts) cannot be copied out,
    // so each repeat builds the world again and steps it to the window untimed: the engines are deterministic,
    // so the window starts from the same state as the first.
    if (frame >= warm_up + window)
        for (int r = 1; r < timing.repeats; ++r) {
            world = engine.make(scene, n);
            for (int f = 0; f < warm_up; ++f) world->step();
            for (int f = 0; f < window; ++f) {
                const auto begin = Clock::now();
                world->step();
                times.push_back(seconds_since(begin));
            }
        }
    result.time_per_step = median(times);
    result.timed_frames = static_cast<int>(times.size());
    return result;
}

}  // namespace impulse::bench
