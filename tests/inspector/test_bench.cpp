// The bench's model without rendering: the Pareto front, the cheapest configuration, the iteration mapping,
// the accuracy metrics on tiny runs, the results files, and its flags. The five files with their pictures
// are checked end to end in the headless program (tests/gui/test_headless.cpp).

#include "bench/bench_metrics.hpp"
#include "bench/bench_plan.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_runs.hpp"
#include "gui/bench_charts.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

namespace impulse::test {

namespace {

std::string scene_text(const std::string& name) {
    std::ifstream in(IMPULSE_SOURCE_DIR "/scenes/" + name + ".json");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

bench::RunResult row(const std::string& scene, const std::string& method, int n, double ms, double error, bool meets) {
    bench::RunResult r;
    r.scene = scene;
    r.method = method;
    r.n = n;
    r.time_per_step = ms * 1e-3;
    r.accuracy.error = error;
    r.accuracy.meets_target = meets;
    r.accuracy.holds = true;
    return r;
}

}  // namespace

TEST_CASE("the Pareto front of a hand-made point set is the points no other beats on both time and error") {
    // By hand: (1, 10) is fastest; (2, 5) and (4, 1) each trade time for error; (3, 6) is beaten by (2, 5);
    // (5, 1) is beaten by (4, 1); the NaN point is never on the front; (2, 5) twice keeps only the first.
    const std::vector<bench::TimeError> points{{3, 6}, {1, 10}, {4, 1}, {2, 5}, {5, 1}, {0.5, NAN}, {2, 5}};
    CHECK(bench::pareto_front(points) == std::vector<std::size_t>{1, 3, 2});
}

TEST_CASE("the Pareto front leaves out runs that failed, so it starts at the fastest run that held") {
    // By hand: (1, 10) is fastest but collapsed; of those that held, (2, 5) is fastest, (4, 1) trades time for
    // error, (3, 6) is beaten by (2, 5). A failed run beats nothing: (0.5, 0.1) failing takes no one off.
    const std::vector<bench::TimeError> points{{3, 6}, {1, 10, false}, {4, 1}, {2, 5}, {0.5, 0.1, false}};
    CHECK(bench::pareto_front(points) == std::vector<std::size_t>{3, 2});
}

TEST_CASE("a stability cell meets the target, holds but misses it (saying by how much), or fails") {
    const bench::BenchScene* stack = bench::find_bench_scene("stack_10");  // top_drift, target 0.05 m
    std::vector<bench::RunResult> rows{
        row("stack_10", "pgs_split", 4, 0.1, 0.03, true), row("stack_10", "pgs_split", 8, 0.2, 0.306, false),
        row("stack_10", "soft_step", 8, 0.1, 0.0295, true), row("stack_10", "book", 8, 0.4, 10.9, false)};
    rows[3].accuracy.holds = false;
    rows[3].accuracy.failure = "collapsed";
    rows[3].accuracy.failure_time = 5.55;
    const bench::StabilityMatrix m = bench::stability_matrix(rows, {"pgs_split", "soft_step", "book"}, {stack});
    // Judged at the largest N: pgs_split held at N = 8 but drifted 0.306 m, 6.1 times the 0.05 m target.
    CHECK(bench::verdict_text(m.cells[0][0]) == "holds, misses target");
    CHECK(bench::cell_text(*stack, m.cells[0][0]) == "6.1 × the target, top_drift 0.306 m");
    CHECK(bench::verdict_text(m.cells[1][0]) == "meets target");
    CHECK(bench::cell_text(*stack, m.cells[1][0]) == "top_drift 0.0295 m");
    CHECK(bench::verdict_text(m.cells[2][0]) == "fails");
    CHECK(bench::cell_text(*stack, m.cells[2][0]) == "collapsed at 5.55 s, top_drift 10.9 m");

    bench::BenchRun run;
    run.scenes = {stack};
    run.methods = {"pgs_split", "soft_step", "book"};
    run.iterations = {4, 8};
    run.rows = rows;
    const std::string md = bench::stability_markdown(run);
    CHECK(md.find("| stack_10 | top_drift <= 0.05 m | **holds, misses target**: 6.1 × the target, top_drift 0.306 m | "
                  "**meets target**: top_drift 0.0295 m | **fails**: collapsed at 5.55 s, top_drift 10.9 m |") !=
          std::string::npos);
}

TEST_CASE("chart markers at one place are moved apart, sideways first, and one alone stays where its data is") {
    using gui::ChartPoint;
    const ChartPoint lo{0, 0}, hi{400, 300};
    // Three runs with the same time and error (book N = 2, 4, 8 at rest), and one elsewhere.
    const std::vector<ChartPoint> at{{100, 100}, {100, 100}, {100, 100}, {300, 50}};
    const std::vector<ChartPoint> drawn = gui::dodged_markers(at, 15.0f, lo, hi);
    REQUIRE(drawn.size() == 4);
    CHECK(drawn[0].x == 100.0f);  // the first keeps its place
    CHECK(drawn[1].x == 115.0f);  // one width to the right
    CHECK(drawn[2].x == 85.0f);   // then to the left
    for (std::size_t i = 0; i < 3; ++i) CHECK(drawn[i].y == 100.0f);
    CHECK(drawn[3].x == 300.0f);
    CHECK(drawn[3].y == 50.0f);
    for (std::size_t i = 0; i < drawn.size(); ++i)
        for (std::size_t j = i + 1; j < drawn.size(); ++j)
            CHECK(std::hypot(drawn[i].x - drawn[j].x, drawn[i].y - drawn[j].y) >= 15.0f);
    // At the plot's left edge, the second goes right and the third further right: never off the plot.
    const std::vector<ChartPoint> edge = gui::dodged_markers({{0, 10}, {0, 10}, {0, 10}}, 15.0f, lo, hi);
    CHECK(edge[1].x == 15.0f);
    CHECK(edge[2].x == 30.0f);
}

TEST_CASE("the cheapest configuration meeting a target is the fastest row of that scene that meets it") {
    const std::vector<bench::RunResult> rows{
        row("stack_10", "book", 1, 0.1, 2.0, false),  // fastest, but misses the target
        row("stack_10", "book", 8, 0.9, 0.01, true), row("stack_10", "pgs", 4, 0.4, 0.02, true),  // the answer
        row("stack_20", "pgs", 1, 0.05, 0.0, true),                                               // another scene
    };
    CHECK(bench::cheapest_meeting_target(rows, "stack_10") == std::optional<std::size_t>(2));
    CHECK(bench::cheapest_meeting_target(rows, "stack_20") == std::optional<std::size_t>(3));
    CHECK_FALSE(bench::cheapest_meeting_target(rows, "grid_1000").has_value());
}

TEST_CASE(
    "an iteration count sets iterations per contact for worst-first, sweeps for sweep and pgs, substeps for "
    "soft_step") {
    ResolverSettings book = *preset("book"), sweep = *preset("sweep"), pgs = *preset("pgs"),
                     split = *preset("pgs_split"), soft = *preset("soft_step");
    for (ResolverSettings* s : {&book, &sweep, &pgs, &split, &soft}) bench::set_iteration_count(*s, 7);
    CHECK(book.iterations.per_contact == 7);
    CHECK(bench::iteration_setting(book) == "iterations_per_contact");
    CHECK(sweep.sweeps == 7);
    CHECK(pgs.sweeps == 7);
    CHECK(split.sweeps == 7);
    CHECK(bench::iteration_setting(pgs) == "sweeps");
    CHECK(soft.soft_step.substeps == 7);
    CHECK(soft.sweeps == 1);
    CHECK(bench::iteration_setting(soft) == "soft_step.substeps");
    // Nothing else changes: the other knobs keep their preset values.
    CHECK(book.sweeps == preset("book")->sweeps);
    CHECK(pgs.iterations == preset("pgs")->iterations);
}

TEST_CASE("a sphere dropped with the book preset bounces with a restitution error near zero") {
    // The ball falls 1 m, about 27 frames; the book's velocity_from_acceleration takes back this frame's g dt,
    // so it leaves at exactly c times the speed it arrived with at the end of the frame before: error ~ 1e-16.
    bench::Timing timing;
    timing.frames = 40;
    timing.repeats = 1;
    const bench::RunResult r =
        bench::run_configuration(scene_text("sphere_drop"), *bench::find_bench_scene("sphere_drop"), "book", 4, timing);
    REQUIRE(r.accuracy.restitution_error.has_value());
    CHECK(*r.accuracy.restitution_error < 1e-9);
    CHECK(r.accuracy.error == *r.accuracy.restitution_error);
    CHECK(r.accuracy.meets_target);
    CHECK(r.frames == 40);
    CHECK(r.timed_frames == 15);  // warm-up 10, then a window of half the 30 frames left
}

TEST_CASE("a top body sinking 0.1 m a frame is reported collapsed at the frame it passed half a box") {
    // Drift after frame f is 0.1 (f + 1) m: 0.5 after frame 4 is not beyond the 0.5 m threshold, 0.6 after
    // frame 5 is, so it collapsed at the end of frame 5: 6 / 60 = 0.1 s.
    Scene scene;
    scene.bodies.resize(2);
    scene.shapes.resize(2);  // no shapes: no contacts
    scene.bodies[1].position = {0, 1.5, 0};
    scene.body_names = {"a", "b"};
    scene.body_materials = {"default", "default"};
    scene.materials["default"] = {};
    const bench::BenchScene spec{"stack", bench::Metric::top_drift, 0.05, 0.5, 10, true};
    bench::AccuracyTracker tracker(scene, spec, 10);
    std::vector<RigidBody> bodies = scene.bodies;
    for (int frame = 0; frame < 10; ++frame) {
        bodies[1].position.y() = 1.5 - 0.1 * (frame + 1);
        CHECK(tracker.observe(frame, bodies, StepReport{}));
    }
    const bench::Accuracy a = tracker.finish(bodies);
    REQUIRE(a.collapse_time.has_value());
    CHECK(*a.collapse_time == doctest::Approx(0.1));
    CHECK_FALSE(a.holds);
    CHECK(a.failure == "collapsed");
    CHECK(a.failure_time == a.collapse_time);
    CHECK(a.error == doctest::Approx(1.0));  // the most it moved
}

TEST_CASE("results.csv of a tiny run has one row per configuration under the documented columns") {
    bench::BenchRun run;
    run.scenes = {bench::find_bench_scene("two_spheres")};
    run.methods = {"book"};
    run.iterations = {1, 2};
    run.timing.frames = 20;
    run.timing.repeats = 1;
    for (const int n : run.iterations)
        run.rows.push_back(bench::run_configuration(scene_text("two_spheres"), *run.scenes[0], "book", n, run.timing));
    const std::string csv = bench::results_csv(run);
    std::istringstream lines(csv);
    std::string header, first, second, extra;
    std::getline(lines, header);
    std::getline(lines, first);
    std::getline(lines, second);
    CHECK_FALSE(std::getline(lines, extra));
    CHECK(header.rfind("scene,metric,unit,target,method,n,iteration_setting,frames,simulated_s,contacts_per_frame,"
                       "time_per_step_ms,timed_frames,error,meets_target,holds,failure,failure_time_s,",
                       0) == 0);
    CHECK(std::count(header.begin(), header.end(), ',') == std::count(first.begin(), first.end(), ','));
    CHECK(first.rfind("two_spheres,momentum_error,,1e-09,book,1,iterations_per_contact,20,", 0) == 0);
    CHECK(second.rfind("two_spheres,momentum_error,,1e-09,book,2,", 0) == 0);
    const auto json = bench::results_json(run, {});
    CHECK(json["rows"].size() == 2);
    CHECK(json["scenes"][0]["frames"] == 20);
    CHECK(json["iteration_mapping"]["book"] == "iterations_per_contact");
    CHECK(bench::stability_markdown(run).find("## Cheapest configuration per scene") != std::string::npos);
}

TEST_CASE("bad bench flags print one line naming the flag, exit with code 2 and write nothing") {
    TempDir dir;
    const std::string out = dir.file("results").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"--scenes", "stak_10"}, "--scenes: no bench scene named \"stak_10\""},
        {{"--methods", "book,bok"}, "--methods: no method named \"bok\""},
        {{"--iterations", "1,x"}, "--iterations: expected counts"},
        {{"--iterations", "0"}, "--iterations: expected counts"},
        {{"--iterations", "2,2"}, "--iterations: 2 is given twice"},
        {{"--repeats", "0"}, "--repeats: must be from 1 to 1000, got 0"},
        {{"--repeats", "three"}, "--repeats: expected a whole number from 1 to 1000, got \"three\""},
        {{"--out", dir.file("missing/deeper").string()}, "--out"},
    };
    for (const auto& [flags, message] : cases) {
        std::vector<std::string> args{"bench", "--frames", "2"};
        args.insert(args.end(), flags.begin(), flags.end());
        if (flags[0] != "--out") args.insert(args.end(), {"--out", out});
        const CliResult r = run_cli(args);
        CAPTURE(r.err);
        CHECK(r.code == 2);
        CHECK(r.err.find("impulse-lab: " + message) == 0);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(r.out.empty());
        CHECK(dir.entries() == 0);
    }
}

}  // namespace impulse::test
