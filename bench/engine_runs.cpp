// A configuration run by another engine (bench/adapters): the same accuracy run, metrics and timing as ours
// (bench_runs.cpp), with the engine's step in place of ours.

#include "bench/bench_runs.hpp"

#include <chrono>
#include <limits>
#include <stdexcept>

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
    std::unique_ptr<EngineWorld> world;
    try {
        world = engine.make(scene, n);
    } catch (const std::exception& e) {
        // A scene the engine cannot hold (MuJoCo 2.2's dense constraint matrix for 1000 boxes, hand-written
        // contacts, ...) is a row that failed with the reason, so the rest of the matrix still runs.
        const double nan = std::numeric_limits<double>::quiet_NaN();
        result.accuracy.error = result.accuracy.end_penetration = nan;
        result.accuracy.failure = std::string("not run: ") + e.what();
        result.time_per_step = nan;
        return result;
    }
    std::vector<RigidBody> bodies = scene.bodies;
    std::vector<double> times;
    long contacts = 0;
    int frame = 0;
    std::string stopped;  // why the engine stopped the run (it ran out of room), if it did
    for (; frame < frames; ++frame) {
        const auto begin = Clock::now();
        try {
            world->step();
        } catch (const std::exception& e) {
            stopped = std::string("engine stopped: ") + e.what();
            break;
        }
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
    if (!stopped.empty()) {
        result.accuracy.failure = stopped;
        result.accuracy.failure_time = frame * scene.settings.duration;
        result.accuracy.holds = result.accuracy.meets_target = false;
        result.time_per_step = median(times);
        result.timed_frames = static_cast<int>(times.size());
        return result;
    }

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
