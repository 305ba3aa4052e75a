// The runs the inspector and the coursework make from a scene stop where `run` stops: at the first frame that
// leaves a body non-finite, with the trace ending before it.

#include "io/scene_file.hpp"
#include "io/trace_json.hpp"
#include "model/runs.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace impulse;

namespace {

// Moving sideways at 1e308 m/s, the body passes the largest double a little after frame 100; nothing touches it.
Scene sideways_bullet() {
    return io::read_scene_text(R"({"bodies": [{"name": "bullet", "shape": {"type": "sphere", "radius": 0.5},
                                               "position": [0, 30, 0], "velocity": [1e308, 0, 0]}]})");
}

}  // namespace

TEST_CASE("run_frames stops at the frame that leaves a body non-finite and the trace ends, valid, before it") {
    const Scene scene = sideways_bullet();
    std::optional<inspect::BrokenRun> broken;
    const Trace trace = inspect::run_frames(scene, TraceFilter{}, 500, {}, &broken);
    REQUIRE(broken.has_value());
    CHECK(broken->frame > 100);
    CHECK(broken->frame < 500);
    CHECK(broken->body.body == 0);
    CHECK(std::string(broken->body.quantity) == "position");
    CHECK_FALSE(broken->body.last_contact.has_value());
    REQUIRE_FALSE(trace.frames.empty());
    CHECK(trace.frames.back().frame == broken->frame - 1);
    CHECK(trace.recording.last_frame == broken->frame - 1);
    CHECK(io::read_trace(io::trace_json(trace)) == trace);  // every number in it is finite
    CHECK(inspect::broken_run_text(scene, *broken) ==
          "frame " + std::to_string(broken->frame) +
              ": body \"bullet\" has a non-finite position after resolution (no contact touched it this frame)");
}

TEST_CASE("run_frames of a scene that stays finite reports nothing broken") {
    Scene scene = sideways_bullet();
    scene.bodies[0].velocity = Vec3(1, 0, 0);
    std::optional<inspect::BrokenRun> broken;
    const Trace trace = inspect::run_frames(scene, TraceFilter{}, 5, {}, &broken);
    CHECK_FALSE(broken.has_value());
    CHECK(trace.frames.size() == 5);
}
