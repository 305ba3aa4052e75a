// `run` says what it records and how a scene's own bench block judges it: a trace that cannot hold the whole run
// is said as soon as the first frames show it, and a scene with a "bench" block gets its verdict after the summary.

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

namespace impulse::test {

TEST_CASE("run --trace without --record says early when the whole run will not fit, and again where it stopped") {
    TempDir dir;
    const CliResult r = run_cli({"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "60", "--trace",
                                 dir.file("t.json").string(), "--max-trace-mb", "1"});
    CHECK(r.code == 0);
    const std::size_t early = r.err.find("the trace keeps the first frames that fit in --max-trace-mb 1");
    const std::size_t end = r.err.find("the trace reached --max-trace-mb 1 at frame");
    CHECK(early != std::string::npos);
    CHECK(end != std::string::npos);
    CHECK(early < end);
    // A run that fits says nothing of the kind.
    const CliResult small = run_cli(
        {"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "5", "--trace", dir.file("s.json").string()});
    CHECK(small.code == 0);
    CHECK(small.err.find("note: --trace") == std::string::npos);
}

TEST_CASE("run judges a scene by its bench block: the metric against the target, over the frames it ran") {
    TempDir dir;
    std::ifstream in(IMPULSE_SOURCE_DIR "/scenes/stack_3.json");
    std::stringstream text;
    text << in.rdbuf();
    std::string scene = text.str();
    scene.insert(scene.find('{') + 1, "\n  \"bench\": {\"metric\": \"top_drift\", \"target\": 0.5, \"duration\": 1},");
    const auto file = dir.write("tower.json", scene);
    const CliResult r = run_cli({"run", file.string(), "--frames", "60"});
    CHECK(r.code == 0);
    CHECK(r.out.find("  bench block: top_drift ") != std::string::npos);
    CHECK(r.out.find(" m, target 0.5 m: meets the target\n") != std::string::npos);
    const CliResult shorter = run_cli({"run", file.string(), "--frames", "30", "--set", "iterations_per_contact=1"});
    CHECK(shorter.out.find("judged over the 30 frames run, the block's duration is 60 frames") != std::string::npos);
    // Without a block, no verdict.
    CHECK(run_cli({"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "5"}).out.find("bench block") ==
          std::string::npos);
}

}  // namespace impulse::test
