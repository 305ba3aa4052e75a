#pragma once
// A shipped scene under a preset, and a run of it through the world, recorded when a trace is given: the tests of the
// whole-step methods (soft step, AVBD) read both.

#include "formats/settings_json.hpp"
#include "record/trace_recorder.hpp"
#include "support/shipped.hpp"
#include "world/world.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impulse::test {

// The shipped scene `name` under `preset`, then each `settings` entry as `--set` would apply it.
inline Scene shipped_under(const std::string& name, const std::string& preset,
                           const std::vector<std::string>& settings = {}) {
    Scene scene = shipped(name);
    formats::apply_setting(scene, "preset=" + preset, "--set");
    for (const std::string& s : settings) formats::apply_setting(scene, s, "--set");
    return scene;
}

// Runs `frames` frames of `scene`, recording them when `trace` is given.
inline std::vector<RigidBody> simulate(const Scene& scene, int frames, Trace* trace = nullptr) {
    World world(scene);
    Recorder nobody;
    std::optional<TraceRecorder> recording;
    if (trace) {
        trace->scene = scene;
        recording.emplace(*trace);
    }
    Recorder& recorder = trace ? static_cast<Recorder&>(*recording) : nobody;
    for (int frame = 0; frame < frames; ++frame) world.step(recorder);
    return world.bodies();
}

}  // namespace impulse::test
