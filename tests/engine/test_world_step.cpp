// The World object: its step is the chapter's frame (integrate, detect, resolve) with the contact memory it
// owns, so warm starting carries from frame to frame without the caller's help; reset and copies start over
// or go on bit for bit.

#include "formats/settings_json.hpp"
#include "methods/method_table.hpp"
#include "record/trace_recorder.hpp"
#include "support/shipped.hpp"
#include "support/simulate.hpp"
#include "body/integrate.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <atomic>
#include <string>
#include <vector>

using namespace impulse;

namespace {

// One frame written out by hand, as every caller wrote it before the world owned its step: integrate (unless
// the velocity method owns the whole step and integrates in its sub-steps), detect, resolve with the memory the
// caller keeps.
// With contact recycling on (soft_step_recycled) the caller keeps the pairs' contacts too.
Detection step_by_hand(const Scene& scene, std::vector<RigidBody>& bodies, ContactMemory* memory, Recorder& recorder,
                       int frame, ContactRecycling* recycling = nullptr) {
    const Damping damping{scene.world.linear_damping, scene.world.angular_damping};
    if (method_row(scene.settings.velocity_method).scope != MethodScope::whole_step)
        for (RigidBody& body : bodies)
            integrate(body, scene.world.gravity, scene.settings.duration, damping, scene.settings.orientation_update);
    Detection detection;
    detect_contacts(scene, bodies, detection, nullptr, scene.settings.recycling.on() ? recycling : nullptr);
    resolve_contacts(bodies, detection.contacts, scene.settings, recorder,
                     {.frame = frame, .memory = memory, .forces = Forces{scene.world.gravity, damping}});
    return detection;
}

}  // namespace

TEST_CASE("a world's step is integrate, detect and resolve with one contact memory, under every preset") {
    // Three boxes stacked: contacts from the first frame on, so the warm-starting presets recall every frame.
    for (const std::string_view preset : preset_names()) {
        CAPTURE(preset);
        const Scene scene = test::shipped_under("stack_3", std::string(preset));
        World world(scene);
        Trace by_world, by_hand;
        by_world.scene = by_hand.scene = scene;
        TraceRecorder world_recorder(by_world), hand_recorder(by_hand);
        std::vector<RigidBody> bodies = scene.bodies;
        ContactMemory memory;
        ContactRecycling recycling;
        for (int frame = 0; frame < 20; ++frame) {
            const StepReport report = world.step(world_recorder);
            const Detection detection = step_by_hand(scene, bodies, &memory, hand_recorder, frame, &recycling);
            CHECK(report.frame == frame);
            CHECK(report.contacts == static_cast<int>(detection.contacts.size()));
            double deepest = 0.0, energy = 0.0;
            for (const Contact& c : detection.contacts) deepest = std::max(deepest, c.penetration);
            for (const RigidBody& b : bodies) energy += kinetic_energy(b);
            CHECK(report.deepest_penetration == deepest);
            CHECK(report.kinetic_energy == energy);
            CHECK_FALSE(report.non_finite);
            REQUIRE(world.bodies() == bodies);  // bit for bit, not approximately
        }
        CHECK(world.frame() == 20);
        CHECK(world.contact_memory().size() == memory.size());
        CHECK(by_world.frames == by_hand.frames);
    }
}

TEST_CASE("a world warm starts its second frame from the first frame's totals without being asked") {
    // A box resting on the ground under pgs: four contacts. The first frame has nothing to recall; the world
    // remembers its four totals, and the second frame opens with four warm-start visits.
    const Scene scene = test::shipped_under("box_resting", "pgs");
    World world(scene);
    Trace trace;
    trace.scene = scene;
    TraceRecorder recorder(trace);
    CHECK(world.contact_memory().size() == 0);
    world.step(recorder);
    CHECK(world.contact_memory().size() == 4);
    world.step(recorder);
    REQUIRE(trace.frames.size() == 2);
    const auto warm_starts = [](const FrameRecord& frame) {
        int n = 0;
        for (const VelocityIteration& it : frame.velocity.iterations)
            n += it.sweep && it.sweep->stage == SolverStage::warm_start;
        return n;
    };
    CHECK(warm_starts(trace.frames[0]) == 0);
    CHECK(warm_starts(trace.frames[1]) == 4);
    CHECK(trace.frames[1].velocity.iterations.front().sweep->stage == SolverStage::warm_start);

    // What a caller that forgot the memory got before: every frame cold. The world's run is not that run.
    std::vector<RigidBody> cold = scene.bodies;
    Recorder nobody;
    for (int frame = 0; frame < 2; ++frame) step_by_hand(scene, cold, nullptr, nobody, frame);
    CHECK(world.bodies() != cold);
}

TEST_CASE("warm_start=false makes a world's second frame the same as a cold one") {
    // The memory is still filled (the trace shows the totals), but nothing recalls it: the switch is the
    // settings', not the caller's.
    Scene scene = test::shipped_under("box_resting", "pgs");
    formats::apply_setting(scene, "warm_start=false", "--set");
    World world(scene);
    std::vector<RigidBody> cold = scene.bodies;
    Recorder nobody;
    for (int frame = 0; frame < 2; ++frame) {
        world.step();
        step_by_hand(scene, cold, nullptr, nobody, frame);
    }
    CHECK(world.bodies() == cold);
}

TEST_CASE("reset returns a world to the scene's start and the same run follows bit for bit") {
    // Soft step: its sub-steps integrate the bodies and warm start from the memory, both of which reset clears.
    const Scene scene = test::shipped_under("stack_3", "soft_step");
    World world(scene);
    for (int frame = 0; frame < 30; ++frame) world.step();
    const std::vector<RigidBody> first = world.bodies();
    CHECK(world.frame() == 30);
    CHECK(world.time() == doctest::Approx(0.5));  // 30 frames of 1/60 s
    CHECK(first != scene.bodies);

    world.reset();
    CHECK(world.frame() == 0);
    CHECK(world.time() == 0.0);
    CHECK(world.contact_memory().size() == 0);
    CHECK(world.bodies() == scene.bodies);
    for (int frame = 0; frame < 30; ++frame) CHECK(world.step().frame == frame);
    CHECK(world.bodies() == first);
}

TEST_CASE("a copy of a world goes on exactly as the world it was copied from") {
    // The bench times a window of frames again from a copy taken where the window starts: bodies, memory and
    // frame number all come along.
    World world(test::shipped_under("stack_3", "pgs"));
    for (int frame = 0; frame < 10; ++frame) world.step();
    World copy = world;
    CHECK(copy.frame() == 10);
    for (int frame = 0; frame < 10; ++frame) {
        const StepReport a = world.step(), b = copy.step();
        CHECK(a.frame == b.frame);
        CHECK(a.resolution == b.resolution);
    }
    CHECK(copy.bodies() == world.bodies());
}

TEST_CASE("a stop flag set before a step cuts every preset's frame short, and a world without one finishes it") {
    // Ctrl-C was looked at between frames only: a frame of 1e8 iterations could not be stopped.
    for (const std::string_view name : preset_names()) {
        const std::string preset(name);
        CAPTURE(preset);
        Scene scene = test::shipped_under("pyramid_10", preset);
        formats::apply_setting(scene, "velocity_iterations=100000000", "--set");
        formats::apply_setting(scene, "position_iterations=100000000", "--set");
        formats::apply_setting(scene, "sweeps=100000", "--set");
        formats::apply_setting(scene, "avbd.iterations=100000", "--set");
        std::atomic<bool> stop{true};
        World world(scene);
        world.set_stop_flag(&stop);
        const StepReport report = world.step();
        CHECK(report.resolution.cut_short);
        // Worst-first looks at the flag before its first visit; a sweeping method (and AVBD) before its first sweep.
        CHECK(report.resolution.velocity.iterations_used + report.resolution.position.iterations_used <=
              static_cast<int>(2 * stop_check_visits));
    }
    World unstoppable(test::shipped_under("pyramid_10", "book"));
    CHECK_FALSE(unstoppable.step().resolution.cut_short);
    std::atomic<bool> stop{false};
    World free(test::shipped_under("pyramid_10", "book"));
    free.set_stop_flag(&stop);
    CHECK_FALSE(free.step().resolution.cut_short);
}
