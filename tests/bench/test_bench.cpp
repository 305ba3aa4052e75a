// The bench's model: the Pareto front, the cheapest configuration, the iteration mapping, the accuracy metrics
// on tiny runs, the results files, and its flags; and the command end to end, its five files with the pictures,
// which it draws with no display. How the pictures are drawn is checked in tests/bench.

#include "bench/bench_merge.hpp"
#include "bench/bench_metrics.hpp"
#include "bench/bench_plan.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_runs.hpp"
#include "bench/bench_charts.hpp"
#include "support/bench_scenes.hpp"
#include "support/png_image.hpp"
#include "bench/bench_charts.hpp"
#include "formats/input_error.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
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
    const bench::BenchScene* stack = bench_scene("stack_10");  // top_drift, target 0.05 m
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
    using bench::ChartPoint;
    const ChartPoint lo{0, 0}, hi{400, 300};
    // Three runs with the same time and error (book N = 2, 4, 8 at rest), and one elsewhere.
    const std::vector<ChartPoint> at{{100, 100}, {100, 100}, {100, 100}, {300, 50}};
    const std::vector<ChartPoint> drawn = bench::dodged_markers(at, 15.0f, lo, hi);
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
    const std::vector<ChartPoint> edge = bench::dodged_markers({{0, 10}, {0, 10}, {0, 10}}, 15.0f, lo, hi);
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
    CHECK(book.iterations_per_contact == 7);
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
    CHECK(pgs.iterations_per_contact == preset("pgs")->iterations_per_contact);
    CHECK(pgs.position_iterations == preset("pgs")->position_iterations);
    CHECK(pgs.velocity_iterations == preset("pgs")->velocity_iterations);
}

TEST_CASE("a sphere dropped with the book preset bounces with a restitution error near zero") {
    // The ball falls 1 m, about 27 frames; the book's velocity_from_acceleration takes back this frame's g dt,
    // so it leaves at exactly c times the speed it arrived with at the end of the frame before: error ~ 1e-16.
    bench::Timing timing;
    timing.frames = 40;
    timing.repeats = 1;
    const bench::RunResult r =
        bench::run_configuration(scene_text("sphere_drop"), *bench_scene("sphere_drop"), "book", 4, timing);
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
    const bench::BenchScene spec{"stack", bench::Metric::top_drift, 0.05, 0.5, 10, true, true};
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
    run.scenes = {bench_scene("two_spheres")};
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
        {{"--scenes", "stak_10"}, "--scenes: no bench scene named \"stak_10\"; did you mean \"stack_10\"?"},
        {{"--methods", "book,bok"}, "--methods: no method named \"bok\"; did you mean \"book\"?"},
        {{"--iterations", "1,x"}, "--iterations: expected counts"},
        {{"--iterations", "0"}, "--iterations: expected counts"},
        {{"--iterations", "2,2"}, "--iterations: 2 is given twice"},
        {{"--repeats", "0"}, "--repeats: must be from 1 to 1000, got 0"},
        {{"--repeats", "three"}, "--repeats: expected a whole number from 1 to 1000, got \"three\""},
        {{"--shard", "3/2"}, "--shard: expected K/N with whole numbers 1 <= K <= N <= 10000 (e.g. 2/4), got \"3/2\""},
        {{"--shard", "1"}, "--shard: expected K/N"},
        {{"--scenes", dir.file("none.json").string()}, "--scenes: cannot read '"},
        {{"--scenes", "two_spheres,two_spheres"}, "--scenes: two scenes are called \"two_spheres\""},
        {{"--methods", "book,havok"}, "--methods: no method named \"havok\""},
        {{"--merge", dir.file("nowhere").string()}, "--merge: cannot read '"},
        {{"--merge", dir.file("nowhere").string(), "--shard", "1/2"}, "--merge: cannot be combined with --shard"},
        {{"--out", dir.file("missing/deeper").string()}, "--out"},
    };
    for (const auto& [flags, message] : cases) {
        std::vector<std::string> args{"bench", "--frames", "2"};
        args.insert(args.end(), flags.begin(), flags.end());
        if (flags[0] != "--out") args.insert(args.end(), {"--out", out});
        if (flags[0] == "--merge") args.erase(args.begin() + 1, args.begin() + 3);  // no --frames
        const CliResult r = run_cli(args);
        CAPTURE(r.err);
        CHECK(r.code == 2);
        CHECK(r.err.find("impulse-lab: " + message) == 0);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(r.out.empty());
        CHECK(dir.entries() == 0);
    }
}

TEST_CASE("a tiny bench run writes all five files, and its charts are legible pictures of the requested data") {
    TempDir dir;
    const auto out = dir.file("bench");
    // No display, and an SDL video driver that does not exist: the charts must not need either.
    const auto keep = [](const char* name) {
        const char* value = std::getenv(name);
        return value ? std::optional<std::string>(value) : std::nullopt;
    };
    const std::optional<std::string> display = keep("DISPLAY"), wayland = keep("WAYLAND_DISPLAY"),
                                     driver = keep("SDL_VIDEODRIVER");
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    ::setenv("SDL_VIDEODRIVER", "no_such_driver", 1);
    const CliResult r = run_cli({"bench", "--scenes", "sphere_drop", "--methods", "book", "--iterations", "1,2",
                                 "--frames", "40", "--repeats", "1", "--out", out.string()});
    const auto restore = [](const char* name, const std::optional<std::string>& value) {
        value ? ::setenv(name, value->c_str(), 1) : ::unsetenv(name);
    };
    restore("DISPLAY", display);
    restore("WAYLAND_DISPLAY", wayland);
    restore("SDL_VIDEODRIVER", driver);
    CAPTURE(r.err);
    REQUIRE(r.code == 0);
    for (const char* name : {"results.csv", "results.json", "speed_accuracy.png", "stability.md", "stability.png"})
        CHECK_MESSAGE(std::filesystem::exists(out / name), name);
    std::ifstream csv(out / "results.csv");
    std::string header, line;
    std::getline(csv, header);
    CHECK(header.starts_with("scene,metric,unit,target,method,n,"));
    int rows = 0;
    while (std::getline(csv, line)) rows += line.starts_with("sphere_drop,restitution_error,,0.01,book,") ? 1 : 0;
    CHECK(rows == 2);
    // One panel (470 x 390 below a 100-pixel header, at least 960 wide): white, with the header's text in ink
    // (30, 30, 30) and book's markers in its colour (0, 114, 178), antialiased into many more colours.
    const PngImage chart = load_png(out / "speed_accuracy.png");
    CHECK(chart.width == 960);
    CHECK(chart.height == 500);
    CHECK(chart.at(0, 0) == 0xFFFFFFu);
    CHECK(distinct_colours(chart) > 20);
    // Dark: every channel at most 60, which only the text in ink and its antialiased edges are.
    int dark = 0, book = 0;
    for (int y = 0; y < chart.height; ++y)
        for (int x = 0; x < chart.width; ++x) {
            const unsigned c = chart.at(x, y);
            dark += (c >> 16) <= 60 && ((c >> 8) & 0xFF) <= 60 && (c & 0xFF) <= 60 ? 1 : 0;
            book += c == 0x0072B2u ? 1 : 0;
        }
    CHECK(dark > 500);
    CHECK(book > 50);
    // No stress scene was run, so the matrix is its header, its legend and its footnote: 240 + 282 + 20 wide.
    const PngImage matrix = load_png(out / "stability.png");
    CHECK(matrix.width == 542);
    CHECK(distinct_colours(matrix) > 20);
}

namespace {

const char* const tower_with_block = R"({
  "ground": {},
  "settings": {"frames": 30},
  "bench": {"metric": "top_drift", "target": 0.02, "duration": 2},
  "bodies": [
    {"name": "low", "shape": {"type": "box", "half_size": [0.5, 0.5, 0.5]}, "position": [0, 0.5, 0]},
    {"name": "high", "shape": {"type": "box", "half_size": [1, 0.25, 1]}, "position": [0, 1.25, 0]}]})";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
}

}  // namespace

TEST_CASE("a scene's bench block gives its metric, target, frames and a collapse at half the top body's height") {
    // By hand: 2 s at the default 1/60 s is 120 frames; the top body is 0.5 m tall (half size 0.25 along gravity),
    // so it has collapsed when it drifted 0.25 m.
    const bench::BenchScene s = bench::declared_bench_scene("tower", tower_with_block);
    CHECK(s.name == "tower");
    CHECK(s.metric == bench::Metric::top_drift);
    CHECK(s.target == 0.02);
    CHECK(s.frames == 120);
    CHECK(s.failure_threshold == doctest::Approx(0.25));
    CHECK(s.stress);
    CHECK(s.verdict);
    // Other metrics fail at 10 x the target unless the block says where; isolated impacts have no verdict column.
    const bench::BenchScene jitter = bench::declared_bench_scene(
        "t", replaced(tower_with_block, R"("metric": "top_drift")", R"("metric": "jitter")"));
    CHECK(jitter.failure_threshold == doctest::Approx(0.2));
    const bench::BenchScene own =
        bench::declared_bench_scene("t", replaced(tower_with_block, R"("duration": 2)", R"("failure_threshold": 0.1)"));
    CHECK(own.failure_threshold == 0.1);
    CHECK(own.frames == 30);  // no duration: the scene's settings.frames
    CHECK_FALSE(bench::declared_bench_scene(
                    "t", replaced(tower_with_block, R"("metric": "top_drift")", R"("metric": "momentum_error")"))
                    .stress);
}

TEST_CASE("a bad bench block is refused naming its field, as the rest of a scene") {
    const std::vector<std::pair<std::string, std::string>> cases{
        {R"("metric": "top_drfit")", "bench.metric"},
        {R"("target": 0.02)", "bench.target"},
        {R"("duration": 2)", "bench.duration"},
    };
    const std::vector<std::string> replacements{R"("metric": "top_drfit")", R"("target": 0)", R"("duration": -1)"};
    const std::vector<std::string> originals{R"("metric": "top_drift")", R"("target": 0.02)", R"("duration": 2)"};
    for (std::size_t i = 0; i < originals.size(); ++i) {
        const std::string text = replaced(tower_with_block, originals[i], replacements[i]);
        CAPTURE(text);
        try {
            bench::declared_bench_scene("t", text);
            FAIL("accepted");
        } catch (const formats::InputError& e) {
            CHECK(e.where() == cases[i].second);
        }
    }
    try {
        bench::declared_bench_scene("t", replaced(tower_with_block, R"("duration": 2)", R"("duraton": 2)"));
        FAIL("accepted");
    } catch (const formats::InputError& e) {
        CHECK(e.where() == "bench.duraton");
    }
}

TEST_CASE("a scene without a bench block gets the general measures and no verdict") {
    const std::string text =
        replaced(tower_with_block, R"("bench": {"metric": "top_drift", "target": 0.02, "duration": 2},)", "");
    const bench::BenchScene s = bench::declared_bench_scene("tower", text);
    CHECK_FALSE(s.verdict);
    CHECK_FALSE(s.stress);
    CHECK(s.frames == 30);
    bench::Timing timing;
    timing.repeats = 1;
    const bench::RunResult r = bench::run_configuration(text, s, "pgs", 8, timing);
    CHECK(r.accuracy.holds);
    CHECK_FALSE(r.accuracy.meets_target);
    CHECK(r.accuracy.failure.empty());
    CHECK(r.accuracy.error == r.accuracy.top_drift_most);  // what the chart shows
    bench::BenchRun run;
    run.scenes = {&s};
    run.methods = {"pgs"};
    run.iterations = {8};
    run.rows = {r};
    // results.csv: the metric it is charted by, and an empty target.
    CHECK(bench::results_csv(run).find("\ntower,top_drift,m,,pgs,8,") != std::string::npos);
    CHECK(bench::results_json(run, {})["scenes"][0]["verdict"] == false);
    CHECK(bench::stability_markdown(run).find("| tower | no bench block: general measures | none | no verdict |") !=
          std::string::npos);
}

TEST_CASE("a shard runs every N-th configuration from the K-th") {
    // By hand: 7 configurations in 3 shards: shard 1 runs 0, 3, 6; shard 2 runs 1, 4; shard 3 runs 2, 5.
    const bench::Shard second{2, 3};
    std::vector<std::size_t> ran;
    for (std::size_t c = 0; c < 7; ++c)
        if (second.runs(c)) ran.push_back(c);
    CHECK(ran == std::vector<std::size_t>{1, 4});
    CHECK(bench::parse_shard("2/3").k == 2);
    CHECK(bench::parse_shard("2/3").n == 3);
    CHECK_THROWS_AS(bench::parse_shard("0/3"), formats::InputError);
    CHECK_THROWS_AS(bench::parse_shard("2/"), formats::InputError);
}

TEST_CASE("shards merged from their results.json give the files one run of the whole matrix gives") {
    bench::BenchRun whole;
    whole.scenes = {bench_scene("two_spheres"), bench_scene("sphere_drop")};
    whole.methods = {"book", "pgs"};
    whole.iterations = {1, 2};
    whole.timing.frames = 12;
    whole.timing.repeats = 1;
    for (const bench::BenchScene* s : whole.scenes)
        for (const std::string& m : whole.methods)
            for (const int n : whole.iterations)
                whole.rows.push_back(bench::run_configuration(scene_text(s->name), *s, m, n, whole.timing));
    whole.rows[3].recording_ratio = 1.25;
    // A configuration an engine could not run (MuJoCo's room): no time, no error. Merging it once failed, reading
    // its null time per step as a number.
    whole.rows[5].time_per_step = std::numeric_limits<double>::quiet_NaN();
    whole.rows[5].accuracy.error = std::numeric_limits<double>::quiet_NaN();
    whole.rows[5].accuracy.holds = whole.rows[5].accuracy.meets_target = false;
    whole.rows[5].accuracy.failure = "not run: too many bodies";
    // Three shards of the 8 configurations, as --shard K/3 runs them, their results.json given in another order.
    std::vector<nlohmann::ordered_json> documents;
    std::vector<std::string> folders;
    for (const int k : {2, 3, 1}) {
        bench::BenchRun shard = whole;
        shard.shard = {k, 3};
        shard.rows.clear();
        for (std::size_t c = 0; c < whole.rows.size(); ++c)
            if (shard.shard.runs(c)) shard.rows.push_back(whole.rows[c]);
        documents.push_back(nlohmann::ordered_json::parse(bench::results_json(shard, {}).dump()));
        folders.push_back("shard-" + std::to_string(k));
    }
    const auto merged = bench::merge_results(documents, folders);
    CHECK(bench::results_csv(merged->run) == bench::results_csv(whole));
    CHECK(bench::stability_markdown(merged->run) == bench::stability_markdown(whole));
    CHECK(bench::results_json(merged->run, {})["merged_from"].size() == 3);

    // A shard missing, a shard twice, a shard of another matrix: refused naming --merge.
    const auto refused = [](const std::vector<nlohmann::ordered_json>& docs, const std::vector<std::string>& names,
                            const std::string& problem) {
        try {
            bench::merge_results(docs, names);
            FAIL("merged");
        } catch (const formats::InputError& e) {
            CHECK(e.where() == "--merge");
            CHECK(e.problem().find(problem) != std::string::npos);
        }
    };
    refused({documents[0], documents[1]}, {"a", "b"}, "shard 1/3 is missing");
    refused({documents[0], documents[0]}, {"a", "b"}, "'b' and 'a' both hold shard 2/3");
    nlohmann::ordered_json other = documents[1];
    other["methods"] = {"book"};
    refused({documents[0], other}, {"a", "b"}, "'b' holds a shard of another matrix than 'a'");
}

}  // namespace impulse::test
