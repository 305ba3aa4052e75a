// The runs the inspector and the coursework make from a scene stop where `run` stops: at the first frame that
// leaves a body non-finite, with the trace ending before it.

#include "formats/scene_file.hpp"
#include "formats/trace_json.hpp"
#include "formats/input_error.hpp"
#include "model/runs.hpp"
#include "model/script.hpp"
#include "model/session.hpp"

#include "support/opened.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace impulse;

namespace {

// Moving sideways at 1e308 m/s, the body passes the largest double a little after frame 100; nothing touches it.
Scene sideways_bullet() {
    return formats::read_scene_text(R"({"bodies": [{"name": "bullet", "shape": {"type": "sphere", "radius": 0.5},
                                               "position": [0, 30, 0], "velocity": [1e308, 0, 0]}]})");
}

}  // namespace

TEST_CASE("run_frames stops at the frame that leaves a body non-finite and the trace ends, valid, before it") {
    const Scene scene = sideways_bullet();
    std::optional<model::BrokenRun> broken;
    const Trace trace = model::run_frames(scene, TraceFilter{}, 500, {}, &broken);
    REQUIRE(broken.has_value());
    CHECK(broken->frame > 100);
    CHECK(broken->frame < 500);
    CHECK(broken->body.body == 0);
    CHECK(std::string(broken->body.quantity) == "position");
    CHECK_FALSE(broken->body.last_contact.has_value());
    REQUIRE_FALSE(trace.frames.empty());
    CHECK(trace.frames.back().frame == broken->frame - 1);
    CHECK(trace.recording.last_frame == broken->frame - 1);
    CHECK(formats::read_trace(formats::trace_json(trace)) == trace);  // every number in it is finite
    CHECK(model::broken_run_text(scene, *broken) ==
          "frame " + std::to_string(broken->frame) +
              ": body \"bullet\" has a non-finite position after resolution (no contact touched it this frame)");
}

TEST_CASE("run_frames of a scene that stays finite reports nothing broken") {
    Scene scene = sideways_bullet();
    scene.bodies[0].velocity = Vec3(1, 0, 0);
    std::optional<model::BrokenRun> broken;
    const Trace trace = model::run_frames(scene, TraceFilter{}, 5, {}, &broken);
    CHECK_FALSE(broken.has_value());
    CHECK(trace.frames.size() == 5);
}

TEST_CASE("the inspector's run stops where its recording is full, so every frame it runs is a frame it shows") {
    model::OpenOptions options;
    options.max_trace_mb = 0.1;  // three frames of the resting box (about 30 kB each, its header aside)
    const model::Session session = test::opened_session("box_resting", options);
    CHECK(session.trace().frames.size() == 3);
    CHECK(session.trace().scene.world.frames == 3);  // what re-running it needs
    CHECK(session.recording_note() ==
          "recorded frames 0..2 of 0..59 (the trace reached --max-trace-mb 0.1 at frame 3)");
    // `run` goes on past it: it writes every frame's states.
    std::optional<int> stopped;
    const Trace whole = model::run_frames(session.trace().scene, TraceFilter{}, 10, {100000, &stopped});
    CHECK(stopped == 3);
    CHECK(whole.scene.world.frames == 10);
    // Nothing to say when everything asked for was recorded.
    CHECK_FALSE(test::opened_session("box_resting").recording_note());
}

TEST_CASE("after a setting changes, the session says which frames the re-run recorded, and a goto beyond names them") {
    model::OpenOptions options;
    options.max_trace_mb = 0.1;
    model::Session session = test::opened_session("box_resting", options);
    // A tiny velocity epsilon makes each frame's velocity phase run many more iterations: one frame fits.
    session.set("velocity_epsilon=0.00001", "script: line 1");
    CHECK(session.trace().frames.size() == 1);
    CHECK(model::rerun_text(session, "velocity_epsilon=0.00001") ==
          "re-ran with velocity_epsilon=0.00001: recorded frame 0 of 0..59 (the trace reached --max-trace-mb 0.1 "
          "at frame 1)");
    try {
        model::perform(session, {model::ActionKind::go_to, "frame=2", 2, 0}, "script: line 2", nullptr);
        FAIL("expected an error");
    } catch (const formats::InputError& e) {
        CHECK(e.what() == std::string("script: line 2: frame 2 is not in the trace (recorded frames: 0..0)"));
    }
    // Back to a setting whose frames fit again.
    session.set("velocity_epsilon=0.01", "script: line 3");
    CHECK(session.trace().frames.size() == 3);
}
