// The bench's scenes and the measures the stress suite added: every bench scene's file declares the block it is
// judged by; sideways drift, drift after settling, the overlap's recovery, Coulomb's slide and a stalled row, each
// on a hand-made motion whose answer is worked out in the test; and the bounce measured where the contact last
// acted, which soft step meets at every sub-step count. Scene runs here are a few dozen frames of small scenes.

#include "bench/bench_metrics.hpp"
#include "bench/bench_plan.hpp"
#include "bench/bench_runs.hpp"
#include "formats/input_error.hpp"
#include "formats/scene_file.hpp"
#include "support/bench_scenes.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

namespace impulse::test {

namespace {

// Two 1 m cubes on the ground, one on the other; `block` is the bench block.
std::string two_cubes(const std::string& block) {
    return R"({"ground": {}, "bench": )" + block + R"(, "bodies": [
        {"name": "low", "shape": {"type": "box", "half_size": [0.5, 0.5, 0.5]}, "position": [0, 0.5, 0]},
        {"name": "top", "shape": {"type": "box", "half_size": [0.5, 0.5, 0.5]}, "position": [0, 1.5, 0]}]})";
}

struct Tracked {
    Scene scene;
    bench::BenchScene spec;
};

Tracked tracked(const std::string& text) {
    return {formats::read_scene_text(text), bench::declared_bench_scene("t", text)};
}

StepReport touching() {
    StepReport report;
    report.contacts = 1;
    return report;
}

}  // namespace

TEST_CASE("every bench scene's file declares the bench block it is judged by, in its suite's folder") {
    int standard = 0, large = 0;
    for (const bench::ShippedScene& s : bench::shipped_bench_scenes()) {
        CAPTURE(s.name);
        const bench::BenchScene spec =
            bench::declared_bench_scene(std::string(s.name), bench_scene_text(std::string(s.name)));
        CHECK(spec.verdict);
        CHECK(spec.target > 0.0);
        (s.suite == bench::Suite::large ? large : standard) += 1;
        CHECK((s.suite == bench::Suite::large) == (std::string(s.file).rfind("large/", 0) == 0));
    }
    CHECK(standard == 23);
    CHECK(large == 1);
    CHECK(bench::suite_named("large") == bench::Suite::large);
    CHECK_THROWS_AS(bench::suite_named("huge"), formats::InputError);
}

TEST_CASE("sideways drift leaves out a settling tower's fall and measures only its move across gravity") {
    // By hand: the top cube sinks 0.3 m and moves 0.03 m along x and 0.04 m along z: sideways 0.05 m.
    Tracked t = tracked(two_cubes(R"({"metric": "top_sideways_drift", "target": 0.06})"));
    bench::AccuracyTracker tracker(t.scene, t.spec, 10);
    std::vector<RigidBody> bodies = t.scene.bodies;
    bodies[1].position += Vec3(0.03, -0.3, 0.04);
    for (int frame = 0; frame < 10; ++frame) tracker.observe(frame, bodies, StepReport{});
    const bench::Accuracy a = tracker.finish(bodies);
    CHECK(a.error == doctest::Approx(0.05));
    CHECK(a.top_drift_most == doctest::Approx(std::sqrt(0.03 * 0.03 + 0.3 * 0.3 + 0.04 * 0.04)));
    CHECK(a.meets_target);
    CHECK(t.spec.failure_threshold == doctest::Approx(0.5));  // half the top cube's height, by default
}

TEST_CASE("with a settle time the drift counts from the state then, but a collapse still counts from the start") {
    // 0.1 s = frame 5's end. The top slides 0.2 m in the first 6 frames, then 0.004 m more: the error is 0.004 m.
    Tracked t = tracked(two_cubes(R"({"metric": "any_drift", "target": 0.01, "settle": 0.1, "duration": 0.5})"));
    REQUIRE(t.spec.settle.has_value());
    bench::AccuracyTracker tracker(t.scene, t.spec, 30);
    std::vector<RigidBody> bodies = t.scene.bodies;
    for (int frame = 0; frame < 30; ++frame) {
        bodies[1].position.x() = frame < 6 ? 0.2 * (frame + 1) / 6.0 : 0.2 + 0.004 * (frame - 5) / 24.0;
        tracker.observe(frame, bodies, StepReport{});
    }
    bench::Accuracy a = tracker.finish(bodies);
    CHECK(a.error == doctest::Approx(0.004));
    CHECK(a.any_drift_most == doctest::Approx(0.204));
    CHECK(a.meets_target);
    // A slide of 0.6 m in the settling time is a collapse (past half the top cube, 0.5 m, at frame 5's end),
    // however still it lies after.
    bench::AccuracyTracker fallen(t.scene, t.spec, 30);
    bodies = t.scene.bodies;
    for (int frame = 0; frame < 30; ++frame) {
        bodies[1].position.x() = frame < 6 ? 0.1 * (frame + 1) : 0.6;
        fallen.observe(frame, bodies, StepReport{});
    }
    a = fallen.finish(bodies);
    CHECK(a.error == doctest::Approx(0.0));  // 0.1 x 6 and 0.6 differ in the last bit
    CHECK(a.failure == "collapsed");
    CHECK(*a.failure_time == doctest::Approx(6 / 60.0));
    // settle applies to the drift metrics only, and must come before the end.
    for (const std::string& block : {std::string(R"({"metric": "jitter", "target": 0.01, "settle": 1})"),
                                     std::string(R"({"metric": "top_drift", "target": 0.01, "settle": 20})")}) {
        CAPTURE(block);
        try {
            bench::declared_bench_scene("t", two_cubes(block));
            FAIL("accepted");
        } catch (const formats::InputError& e) {
            CHECK(e.where() == "bench.settle");
        }
    }
}

TEST_CASE("once settled, a top that crumbles straight down has collapsed, though it moved little sideways") {
    // By hand: settle at 0.1 s (frame 5's end). The top drops 0.3 m by then (a tower falling into place: no
    // collapse), then 1 cm aside and 0.1 m lower each frame: from the settled state it has moved
    // sqrt(0.01^2 + (0.1 (f - 5))^2), past the 0.5 m threshold at frame 10's end, 11 / 60 s; sideways, 1 cm.
    Tracked t =
        tracked(two_cubes(R"({"metric": "top_sideways_drift", "target": 0.05, "settle": 0.1, "duration": 0.5})"));
    bench::AccuracyTracker tracker(t.scene, t.spec, 30);
    std::vector<RigidBody> bodies = t.scene.bodies;
    for (int frame = 0; frame < 30; ++frame) {
        const double drop = frame < 6 ? 0.05 * (frame + 1) : std::min(0.9, 0.3 + 0.1 * (frame - 5));
        bodies[1].position = t.scene.bodies[1].position + Vec3(frame < 6 ? 0.0 : 0.01, -drop, 0);
        tracker.observe(frame, bodies, StepReport{});
    }
    const bench::Accuracy a = tracker.finish(bodies);
    CHECK(a.error == doctest::Approx(0.01));
    CHECK(a.failure == "collapsed");
    CHECK(*a.failure_time == doctest::Approx(11 / 60.0));
}

TEST_CASE("a bounce is measured where the contact last acted: free flight still inside the ground is no part of it") {
    // A ball of restitution 0.5 arrives at -4 m/s (the end of the frame before contact). In the first contact frame
    // it leaves at +2 m/s; it is still below the ground's surface for the next frame, which only gravity acts on
    // (2 - g h). v_after is the 2 m/s: error |2 - 0.5 x 4| / 2 = 0. Counting the free-flight frame, as the bench
    // did before, would have charged gravity's g h / 2 = 8.2 % to the restitution.
    const std::string text = R"({"ground": {"material": "rubber"}, "materials": {"rubber": {"restitution": 0.5}},
        "bench": {"metric": "restitution_error", "target": 0.01},
        "bodies": [{"shape": {"type": "sphere", "radius": 0.5}, "position": [0, 0.6, 0], "velocity": [0, -4, 0]}]})";
    Tracked t = tracked(text);
    const double h = t.scene.settings.duration, g = 9.81;
    bench::AccuracyTracker tracker(t.scene, t.spec, 4);
    std::vector<RigidBody> bodies = t.scene.bodies;
    bodies[0].velocity.y() = 2.0;
    tracker.observe(0, bodies, touching());  // the bounce
    bodies[0].velocity.y() = 2.0 - g * h;
    tracker.observe(1, bodies, touching());  // flying out, still overlapping: exactly gravity's change
    bodies[0].velocity.y() -= g * h;
    tracker.observe(2, bodies, StepReport{});  // clear of the ground
    const bench::Accuracy a = tracker.finish(bodies);
    REQUIRE(a.restitution_error.has_value());
    CHECK(*a.restitution_error == doctest::Approx(0.0).epsilon(1e-12));
    // A frame in which the contact does act (here it pushes 0.1 m/s more) is part of the bounce.
    bench::AccuracyTracker pushed(t.scene, t.spec, 4);
    bodies = t.scene.bodies;
    bodies[0].velocity.y() = 2.0;
    pushed.observe(0, bodies, touching());
    bodies[0].velocity.y() = 2.1 - g * h;
    pushed.observe(1, bodies, touching());
    CHECK(*pushed.finish(bodies).restitution_error == doctest::Approx(std::abs(0.1 - g * h) / 2.0).epsilon(1e-9));
}

TEST_CASE("soft step's bounce on sphere_drop is exact to 1 % at 1, 2, 4 and 8 sub-steps") {
    // Its restitution pass sets v_n = -c v_n,before after the sub-steps (Box2D v3's), and the bench measures the
    // bounce where the contact last acted (docs/methods.md, "Bounces"). The ball lands in frame 27 or 28: 45 frames.
    bench::Timing timing;
    timing.frames = 45;
    timing.repeats = 1;
    for (const int n : {1, 2, 4, 8}) {
        CAPTURE(n);
        const bench::RunResult r = bench::run_configuration(bench_scene_text("sphere_drop"),
                                                            *bench_scene("sphere_drop"), "soft_step", n, timing);
        REQUIRE(r.accuracy.restitution_error.has_value());
        CHECK(*r.accuracy.restitution_error < 0.01);
        CHECK(r.accuracy.meets_target);
    }
}

TEST_CASE("AVBD holds heavy_on_light's boxes of 10^6 to 5 10^7 kg from one iteration, its penalty per kilogram") {
    // Jolt's heavy-on-light scene, judged by its bench block (any body's drift within 5 cm). With beta, k_min and k_max
    // in N/m (tuned for 1 kg boxes) every box fell as if nothing held it and the scene collapsed at 0.32 s at every
    // N; per kilogram of the lighter body (derivation/avbd/mass_scaled_penalty.hpp) it stands. Measured over 10 s:
    // 2.0 cm at N = 1, 3.8 mm at N = 4. Here 2 s, past the old collapse.
    bench::Timing timing;
    timing.frames = 120;
    timing.repeats = 1;
    for (const int n : {1, 4}) {
        CAPTURE(n);
        const bench::RunResult r = bench::run_configuration(bench_scene_text("heavy_on_light"),
                                                            *bench_scene("heavy_on_light"), "avbd", n, timing);
        CHECK(r.accuracy.holds);
        CHECK(r.accuracy.failure.empty());
        CHECK(r.accuracy.meets_target);
        CHECK(r.accuracy.error < 0.05);
    }
}

TEST_CASE(
    "an overlapping pile counts as apart once its deepest penetration is 5 % of the start's, and then must be "
    "slow") {
    // By hand: the two cubes start 0.2 m into each other. They are pushed apart over frames 0-2, at 0.15, 0.05 and
    // 0.005 m of overlap (0.005 <= 5 % of 0.2 = 0.01): apart at the end of frame 2, 3 / 60 s. The top cube then
    // moves at 0.5 m/s, under the 1 m/s default leave_speed; at 3 m/s it has exploded.
    const std::string text = R"({"ground": {}, "gravity": [0, 0, 0],
        "bench": {"metric": "recovery_time", "target": 0.1},
        "bodies": [{"shape": {"type": "box", "half_size": [0.5, 0.5, 0.5]}, "position": [0, 0.5, 0]},
                   {"shape": {"type": "box", "half_size": [0.5, 0.5, 0.5]}, "position": [0, 1.3, 0]}]})";
    Tracked t = tracked(text);
    REQUIRE(t.spec.leave_speed.has_value());
    CHECK(*t.spec.leave_speed == 1.0);
    for (const double speed : {0.5, 3.0}) {
        CAPTURE(speed);
        bench::AccuracyTracker tracker(t.scene, t.spec, 6);
        std::vector<RigidBody> bodies = t.scene.bodies;
        const double overlaps[] = {0.15, 0.05, 0.005, -0.01, -0.02, -0.03};
        for (int frame = 0; frame < 6; ++frame) {
            bodies[1].position.y() = 1.5 - overlaps[frame];
            bodies[1].velocity.y() = frame >= 2 ? speed : 1.0;
            tracker.observe(frame, bodies, StepReport{});
        }
        const bench::Accuracy a = tracker.finish(bodies);
        REQUIRE(a.recovery_time.has_value());
        CHECK(*a.recovery_time == doctest::Approx(3 / 60.0));
        CHECK(*a.leave_speed == doctest::Approx(speed));
        CHECK(a.holds == (speed < 1.0));
        if (speed > 1.0) CHECK(a.failure == "exploded");
    }
    // Never apart: it fails, with no time.
    bench::AccuracyTracker stuck(t.scene, t.spec, 3);
    for (int frame = 0; frame < 3; ++frame) stuck.observe(frame, t.scene.bodies, StepReport{});
    const bench::Accuracy a = stuck.finish(t.scene.bodies);
    CHECK(a.failure == "stays overlapped");
    CHECK(std::isnan(a.error));
}

TEST_CASE("a box sliding to a stop is compared with Coulomb's v0^2 / (2 mu g) on level ground") {
    // By hand: friction sqrt(0.8 x 0.2) = 0.4, v0 = 2 m/s, g = 9.81: it stops after t_s = 2 / 3.924 = 0.51 s,
    // having slid 4 / 7.848 = 0.5097 m; a run of 1 s ends stopped. Put 0.5 m along: error (0.5097 - 0.5) / 0.5097.
    const std::string text = R"({"ground": {"material": "slab"},
        "materials": {"slab": {"friction": 0.2}, "block": {"friction": 0.8}},
        "bench": {"metric": "slide_error", "target": 0.05, "duration": 1},
        "bodies": [{"shape": {"type": "box", "half_size": [0.5, 0.25, 0.5]}, "position": [0, 0.25, 0],
                    "velocity": [0, 0, 2], "material": "block"}]})";
    Tracked t = tracked(text);
    bench::AccuracyTracker tracker(t.scene, t.spec, 60);
    std::vector<RigidBody> bodies = t.scene.bodies;
    bodies[0].position.z() = 0.5;
    for (int frame = 0; frame < 60; ++frame) tracker.observe(frame, bodies, StepReport{});
    const double exact = 4.0 / (2 * 0.4 * 9.81);
    const bench::Accuracy a = tracker.finish(bodies);
    REQUIRE(a.slide_error.has_value());
    CHECK(*a.slide_error == doctest::Approx((exact - 0.5) / exact));
    CHECK(a.meets_target);
    // The metric needs level ground and a body that starts sliding along it.
    for (const auto& [from, to] : {std::pair<std::string, std::string>{
                                       R"("ground": {"material")", R"("ground": {"normal": [0.1, 1, 0], "material")"},
                                   {R"("velocity": [0, 0, 2])", R"("velocity": [0, -1, 2])"},
                                   {R"("velocity": [0, 0, 2])", R"("velocity": [0, 0, 0])"}}) {
        std::string bad = text;
        bad.replace(bad.find(from), from.size(), to);
        CAPTURE(bad);
        CHECK_THROWS_AS(bench::declared_bench_scene("t", bad), formats::InputError);
    }
}

TEST_CASE("a body that never moves min_travel from its start stalls the run") {
    // A row of dominoes must all fall: the low cube here never moves, the top one moves 0.5 m.
    Tracked t = tracked(two_cubes(R"({"metric": "jitter", "target": 0.01, "min_travel": 0.3})"));
    bench::AccuracyTracker tracker(t.scene, t.spec, 10);
    std::vector<RigidBody> bodies = t.scene.bodies;
    bodies[1].position.x() = 0.5;
    for (int frame = 0; frame < 10; ++frame) tracker.observe(frame, bodies, StepReport{});
    const bench::Accuracy a = tracker.finish(bodies);
    CHECK(a.least_travel == 0.0);
    CHECK(a.failure == "stalled");
    CHECK_FALSE(a.holds);
}

}  // namespace impulse::test
