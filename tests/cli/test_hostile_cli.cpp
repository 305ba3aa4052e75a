// The program as an attacker or a careless user meets it (issue 29): each case is named after what went wrong
// before it was held.

#include "support/capped_run.hpp"
#include "support/program.hpp"
#include "support/read_text.hpp"
#include "support/run_cli.hpp"
#include "support/shipped.hpp"
#include "support/temp_dir.hpp"
#include "support/terminal.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using impulse::test::CliResult;
using impulse::test::read_text;
using impulse::test::run_cli;
using impulse::test::TempDir;

namespace {

using impulse::test::program;
using impulse::test::ruler;

}  // namespace

TEST_CASE("an escape sequence in a body's name reaches a terminal shown, not obeyed") {
    // Terminal escape sequences from a file reached the teacher's terminal.
    TempDir dir;
    const auto scene = dir.write("evil.json", R"({"bodies": [{"name": "\u001b[2J\u001b]0;owned\u0007ball",
        "shape": {"type": "sphere", "radius": 0.5}, "position": [0, 2, 0]}], "ground": {}})");
    impulse::test::Terminal t({program, "run", scene.string(), "--frames", "2"}, {});
    const std::string shown = t.expect("mm from where it started");
    CHECK(shown.find("\\x1b[2J\\x1b]0;owned\\x07ball") != std::string::npos);
    CHECK(shown.find('\x1b') == std::string::npos);
    CHECK(shown.find('\x07') == std::string::npos);
}

TEST_CASE("a JSON key holding a line break gives an error of one line") {
    // The key's line break made a two-line error.
    TempDir dir;
    const auto scene = dir.write("key.json", "{\"bodies\": [], \"bad\\nkey\\u001b[31m\": 1}");
    const CliResult r = run_cli({"validate", scene.string()});
    CHECK(r.code == 1);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find("bad\\nkey\\x1b[31m") != std::string::npos);
}

TEST_CASE("the same file as --trace and --states is one error before the run, and the trace is not lost") {
    // `run --trace X --states X` exited 0 and the trace was lost.
    TempDir dir;
    const std::string same = dir.file("out.json").string();
    const CliResult r =
        run_cli({"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "3", "--trace", same, "--states", same});
    CHECK(r.code == 2);
    CHECK(r.err == "impulse-lab: --states: '" + same +
                       "' is also --trace's file: one output would replace the other; choose another file\n");
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(same));
}

TEST_CASE("no output replaces the file it is made from: run, resolve, worksheet and inspect") {
    TempDir dir;
    const std::string scene = dir.write("scene.json", read_text(IMPULSE_SOURCE_DIR "/scenes/stack_3.json")).string();
    const std::string before = read_text(scene);
    std::filesystem::create_symlink(scene, dir.file("link.json"));
    const std::vector<std::vector<std::string>> commands{
        {"run", scene, "--frames", "2", "--trace", scene},
        {"run", scene, "--frames", "2", "--states", dir.file("link.json").string()},
        {"resolve", scene, "--trace", dir.file("./scene.json").string()},
        {"worksheet", scene, "--frames", "1", "--out", scene},
        {"inspect", scene, "--headless", "--screenshot", scene},
    };
    for (const std::vector<std::string>& args : commands) {
        CAPTURE(args[0]);
        const CliResult r = run_cli(args);
        CHECK(r.code == 2);
        CHECK(r.err.find("which this command reads: writing it would replace it") != std::string::npos);
        CHECK(read_text(scene) == before);
    }
}

TEST_CASE("diff --out cannot replace a student's file, the reference, or a report file with another") {
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    const std::string sheet = dir.file("class/ada.csv").string();
    REQUIRE(run_cli({"worksheet", ruler, "--out", sheet}).code == 0);
    REQUIRE(run_cli({"worksheet", ruler, "--out", dir.file("class/summary.csv").string()}).code == 0);
    const std::string before = read_text(sheet);
    // One file: --out over the student's file.
    CliResult r = run_cli({"diff", ruler, sheet, "--out", sheet});
    CHECK(r.code == 2);
    CHECK(r.err.find("which this command reads: writing it would replace it") != std::string::npos);
    // A class: the report into the class folder would replace its summary.csv (a student's file).
    r = run_cli({"diff", ruler, dir.file("class").string(), "--out", dir.file("class").string()});
    CHECK(r.code == 2);
    CHECK(read_text(sheet) == before);
    CHECK_FALSE(std::filesystem::exists(dir.file("class/cells.csv")));
}

TEST_CASE("a temporary left by a writer that was killed is removed by the next write to the same file") {
    // SIGKILL during a write left a hidden temporary that nothing ever removed.
    TempDir dir;
    const std::string trace = dir.file("trace.json").string();
    // A writer killed mid-write: its process is gone (a child that exited), its temporary is left.
    const pid_t gone = ::fork();
    if (gone == 0) ::_exit(0);
    ::waitpid(gone, nullptr, 0);
    const auto orphan = dir.write(".trace.json.tmp-" + std::to_string(gone) + "-Ab12Cd", "{\"half\": ");
    // One whose writer still runs (this process) is not an orphan.
    const auto live = dir.write(".trace.json.tmp-" + std::to_string(::getpid()) + "-Ef34Gh", "{\"being written");
    REQUIRE(run_cli({"resolve", ruler, "--trace", trace}).code == 0);
    CHECK_FALSE(std::filesystem::exists(orphan));
    CHECK(std::filesystem::exists(live));
    CHECK(std::filesystem::exists(trace));
}

TEST_CASE("a flag given twice is named as given twice, not as missing its value") {
    // `--frames 2 --frames 3` said "--frames: needs a value".
    const CliResult r = run_cli({"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "2", "--frames", "3"});
    CHECK(r.code == 2);
    CHECK(r.err ==
          "impulse-lab: --frames: given 2 times; it takes one value, give it once; see impulse-lab run --help\n");
}

TEST_CASE("a run of gravity -1e308 keeps its summary rows one per line") {
    // The depths came to 300 digits; the fixed-width row was cut, and its line break with it.
    TempDir dir;
    std::string scene = read_text(IMPULSE_SOURCE_DIR "/scenes/stack_3.json");
    scene.insert(scene.find('{') + 1, "\"gravity\": [0, -1e308, 0], ");
    const CliResult r = run_cli({"run", dir.write("heavy.json", scene).string(), "--frames", "30"});
    CHECK(r.code == 0);
    std::istringstream lines(r.out);
    std::string line;
    std::size_t rows = 0;
    while (std::getline(lines, line))
        if (line.size() > 2 && line[2] == ' ' && std::isdigit(static_cast<unsigned char>(line[6]))) {
            ++rows;
            CHECK_MESSAGE(line.size() < 80, line);
        }
    CHECK(rows == 16);  // frames 0, 2, ..., 28 and the last, 29
}

TEST_CASE("a class folder's broken link and FIFO get a row each, whatever order the folder lists them in") {
    // A bad symlink was the whole folder's error ("cannot list the folder"), or skipped with no row.
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    REQUIRE(run_cli({"worksheet", ruler, "--out", dir.file("class/ben.csv").string()}).code == 0);
    std::filesystem::create_symlink(dir.file("gone.csv"), dir.file("class/ada.csv"));
    std::filesystem::create_symlink(dir.file("gone.csv"), dir.file("class/zed.csv"));
    REQUIRE(::mkfifo(dir.file("class/pipe.csv").c_str(), 0600) == 0);
    const CliResult r = run_cli({"diff", ruler, dir.file("class").string(), "--format", "csv"});
    CHECK(r.code == 1);
    CHECK(r.out.find("ada.csv,,,,,,,,,\"a link to " + dir.file("gone.csv").string() + ", which does not exist\"") !=
          std::string::npos);
    CHECK(r.out.find("zed.csv,,,,,,,,,\"a link to ") != std::string::npos);
    CHECK(r.out.find("pipe.csv,,,,,,,,,\"not a file (a FIFO, a socket or a device): not read\"") != std::string::npos);
    CHECK(r.out.find("ben.csv,worksheet,89,0,0,89,0.0,") != std::string::npos);
}

TEST_CASE("3000 spheres at one point are refused as more contacts than a frame may resolve, within 1 GiB") {
    // A 138 KB scene of 3000 spheres at one point exhausted 4 GB (4.5 million touching pairs) and exited 70.
    TempDir dir;
    std::string bodies;
    for (int i = 0; i < 3000; ++i)
        bodies += std::string(i ? ", " : "") + R"({"name": "s)" + std::to_string(i) +
                  R"(", "shape": {"type": "sphere", "radius": 0.5}, "position": [0, 1, 0]})";
    const auto scene = dir.write("pile.json", R"({"bodies": [)" + bodies + "]}");
    for (const std::string command : {"run", "resolve"}) {
        CAPTURE(command);
        std::vector<std::string> args{program, command, scene.string()};
        if (command == "run") args.insert(args.end(), {"--frames", "2"});
        const auto r = impulse::test::run_capped(args, 1ull << 30, 60);
        CHECK(r.code == 2);
        CHECK(r.err == "impulse-lab: " + scene.string() +
                           ": frame 0: the bodies' shapes touch in more than 250000 contacts, more than a frame may "
                           "resolve (are many bodies piled at one point?)\n");
        MESSAGE(command << ": peak " << r.peak_kib / 1024 << " MiB, " << r.seconds << " s");
    }
}

TEST_CASE("Ctrl-C while run waits for a FIFO's reader exits 130, not 2") {
    // The wait gave up with "cannot write" and exit 2, as if the path were wrong.
    TempDir dir;
    const std::string fifo = dir.file("trace.fifo").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const auto r = impulse::test::run_capped(
        {program, "run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "2", "--trace", fifo}, 1ull << 30, 30,
        {SIGINT, 700});
    CHECK(r.code == 130);
    CHECK(r.err ==
          "impulse-lab: interrupted (SIGINT) while --trace '" + fifo + "' waited for its reader: it got nothing\n");
    CHECK(std::filesystem::is_fifo(fifo));
}

TEST_CASE("Ctrl-C stops a frame of a hundred million iterations at once and keeps the frames done") {
    // The resolver's loops did not look at Ctrl-C: one frame ran on for minutes after it.
    TempDir dir;
    const std::string trace = dir.file("t.json").string();
    const auto r = impulse::test::run_capped(
        {program, "run", IMPULSE_SOURCE_DIR "/scenes/stack_10.json", "--frames", "3", "--set",
         "velocity_iterations=100000000", "--set", "velocity_epsilon=0", "--trace", trace, "--keep-partial"},
        1ull << 30, 60, {SIGINT, 1000});
    CHECK(r.code == 130);
    CHECK(r.err.find("impulse-lab: interrupted (SIGINT) after 0 of 3 frames: the frames done are written\n") !=
          std::string::npos);
    CHECK(r.seconds < 10.0);  // without the stop flag the frame ran on past the time limit (60 s)
    CHECK(run_cli({"validate", trace}).code == 0);
    MESSAGE("stopped " << r.seconds - 1.0 << " s after the signal");
}

TEST_CASE("a long run's trace and states are written as they go: its memory does not grow with its frames") {
    // --states had no bound (out of memory after 40 s); --max-trace-mb 1000 peaked at 3.2 GB.
    TempDir dir;
    const auto peak = [&](const std::string& scene, const std::string& frames, const std::string& flag) {
        const auto r = impulse::test::run_capped({program, "run", IMPULSE_SOURCE_DIR "/scenes/" + scene, "--frames",
                                                  frames, flag, dir.file("out").string(), "--max-trace-mb", "1000"},
                                                 2ull << 30, 120);
        CHECK(r.code == 0);
        const auto bytes = std::filesystem::file_size(dir.file("out"));
        MESSAGE(scene << ", " << frames << " frames, " << flag << ": " << (bytes >> 20) << " MiB written, peak "
                      << r.peak_kib / 1024 << " MiB, " << r.seconds << " s");
        return std::pair{bytes, r.peak_kib * 1024};
    };
    // Under AddressSanitizer the peaks mean nothing (its shadow memory and quarantine), so the runs there have a fifth
    // of the frames or fewer and check only that the outputs grow with them.
    struct Runs {
        const char *states_short, *states_long, *trace_short, *trace_long;  // frames
        unsigned states_growth_mib, trace_growth_mib;                       // at least, from short to long
    };
    const bool sanitized = impulse::test::address_sanitized;
    const Runs runs = sanitized ? Runs{"2000", "10000", "1", "6", 5, 5} : Runs{"10000", "50000", "4", "20", 25, 30};
    const auto [states_short, states_short_peak] = peak("stack_3.json", runs.states_short, "--states");
    const auto [states_long, states_long_peak] = peak("stack_3.json", runs.states_long, "--states");
    CHECK(states_long - states_short > runs.states_growth_mib << 20);
    if (!sanitized) CHECK(states_long_peak - states_short_peak < 8 << 20);
    const auto [trace_short, trace_short_peak] = peak("stack_10.json", runs.trace_short, "--trace");
    const auto [trace_long, trace_long_peak] = peak("stack_10.json", runs.trace_long, "--trace");
    CHECK(trace_long - trace_short > runs.trace_growth_mib << 20);
    if (!sanitized) CHECK(trace_long_peak - trace_short_peak < 16 << 20);
}

TEST_CASE("--max-states-mb bounds --states on disk: the CSV ends with a whole frame, two notes say where") {
    // --states had no size bound: 100000 frames of grid_1000 would have written about 23 GB.
    TempDir dir;
    const std::string states = dir.file("s.csv").string();
    const CliResult r = run_cli({"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "500", "--states",
                                 states, "--max-states-mb", "0.05"});
    CHECK(r.code == 0);
    const std::string csv = read_text(states);
    CHECK(csv.size() <= 50000);
    // Whole frames only: every frame from -1 to the last has its three bodies, and the file ends with a row's end.
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line);
    CHECK(line.rfind("frame,time,body,", 0) == 0);
    int rows = 0, last_frame = -2;
    while (std::getline(lines, line)) {
        const int frame = std::stoi(line);
        CHECK(frame == (rows / 3) - 1);
        last_frame = frame;
        ++rows;
    }
    CHECK(rows % 3 == 0);
    CHECK(csv.back() == '\n');
    REQUIRE(last_frame > 10);
    CHECK(r.err.find("impulse-lab: note: --states: at ") != std::string::npos);
    CHECK(r.err.find("the states keep the first frames that fit in --max-states-mb 0.05") != std::string::npos);
    CHECK(r.err.find("impulse-lab: note: the states reached --max-states-mb 0.05 at frame " +
                     std::to_string(last_frame + 1) + " and end with frame " + std::to_string(last_frame) + ";") !=
          std::string::npos);
    CHECK(r.out.find("500 frames") != std::string::npos);  // the run went on to its end
    // A run that fits says nothing.
    const CliResult small = run_cli({"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "5", "--states",
                                     states, "--max-states-mb", "0.05"});
    CHECK(small.code == 0);
    CHECK(small.err.find("--max-states-mb") == std::string::npos);
}
