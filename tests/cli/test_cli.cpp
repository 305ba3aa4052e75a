// The command line as a user meets it: the main job, validation, help and version, and one-line errors
// with exit code 2 for bad flags.

#include "support/run_cli.hpp"
#include "support/shipped.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>

using namespace impulse::test;

namespace {

using impulse::test::cases;

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("resolve --explain prints every derivation step of the ruler as an annotated table") {
    const CliResult r = run_cli({"resolve", cases + "ruler.json", "--explain"});
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    // Each table is titled by its step's name (the chapter's step numbers differ from method to method).
    const char* steps[] = {"basis — ",
                           "relative_position — ",
                           "delta_velocity_per_unit_impulse — ",
                           "contact_velocity — ",
                           "desired_delta_velocity — ",
                           "impulse — ",
                           "velocity_change — ",
                           "penetration_inertia — ",
                           "move_split — ",
                           "position_change — "};
    std::size_t titles = 0;
    for (const char* step : steps) {
        CHECK_MESSAGE(r.out.find(std::string("\n") + step) != std::string::npos, step);
        titles += count_of(r.out, std::string("\n") + step);
    }
    // Every table has the five columns, and the chapter's equations appear beside their values.
    CHECK(count_of(r.out, "quantity") == titles + count_of(r.out, "\nupdates — "));
    CHECK(r.out.find("formula") != std::string::npos);
    for (const char* equation : {"(1.8)", "(14.1)", "(14.2)", "(14.3)", "(9.5)", "(7.5)"})
        CHECK_MESSAGE(r.out.find(equation) != std::string::npos, equation);
    CHECK(r.out.find("u = q_rel × n") != std::string::npos);
}

TEST_CASE("resolve writes a trace that validate accepts, and says where it went") {
    TempDir dir;
    const std::string trace = dir.file("ruler.trace.json").string();
    const CliResult r = run_cli({"resolve", cases + "ruler.json", "--trace", trace});
    CHECK(r.code == 0);
    CHECK(r.out.find("trace written to " + trace) != std::string::npos);
    const CliResult v = run_cli({"validate", trace});
    CHECK(v.code == 0);
    CHECK(v.out == trace + ": valid trace (format version 2, 1 frame, 2 iterations)\n");
}

TEST_CASE("every shipped case validates") {
    std::vector<std::string> args{"validate"};
    for (const auto& entry : std::filesystem::directory_iterator(cases)) args.push_back(entry.path().string());
    REQUIRE(args.size() > 5);
    const CliResult r = run_cli(args);
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    CHECK(count_of(r.out, ": valid case (") == args.size() - 1);
}

TEST_CASE("validate checks every file and gives the verdict invalid (1) if any is") {
    TempDir dir;
    const std::string bad = dir.write("bad.json", R"({"bodies": [], "contacts": []})").string();
    const CliResult r = run_cli({"validate", cases + "ruler.json", bad});
    CHECK(r.code == impulse::cli::exit_verdict);
    CHECK(r.out == cases + "ruler.json: valid case (1 body, 1 contact)\n");
    CHECK(r.err == "impulse-lab: " + bad + ": bodies: must have at least 1 item, got 0\n");
}

TEST_CASE("--version and --help answer with exit code 0") {
    const CliResult version = run_cli({"--version"});
    CHECK(version.code == 0);
    CHECK(version.out.rfind("impulse-lab ", 0) == 0);
    const CliResult help = run_cli({"--help"});
    CHECK(help.code == 0);
    CHECK(help.out.find("resolve") != std::string::npos);
    const CliResult resolve_help = run_cli({"resolve", "--help"});
    CHECK(resolve_help.code == 0);
    CHECK(resolve_help.out.find("--explain") != std::string::npos);
    const CliResult validate_help = run_cli({"validate", "--help"});
    CHECK(validate_help.code == 0);
}

TEST_CASE("impulse-lab help [COMMAND] prints the program's or the command's help") {
    const CliResult all = run_cli({"help"});
    CHECK(all.code == 0);
    for (const char* command : {"resolve", "run", "inspect", "lesson", "validate", "worksheet", "diff", "bench"})
        CHECK_MESSAGE(all.out.find(std::string("\n  ") + command + " ") != std::string::npos, command);
    CHECK(all.out.find("Exit codes: 0 done; 1 a verdict;") != std::string::npos);
    const CliResult run = run_cli({"help", "run"});
    CHECK(run.code == 0);
    CHECK(run.out.find("Usage: impulse-lab run [OPTIONS] SCENE") != std::string::npos);
    CHECK(run.out == run_cli({"run", "--help"}).out);
    const CliResult unknown = run_cli({"help", "rnu"});
    CHECK(unknown.code == 2);
    CHECK(unknown.err.rfind("impulse-lab: unknown command \"rnu\" (did you mean run?)", 0) == 0);
}

TEST_CASE("the help says every value in words, never in CLI11's type names") {
    // Regression: the help showed "--frames INT:INT in 1 to 10000000", "--dt FLOAT:NUMBER in 1e-06 to 10" and
    // "--preset TEXT:{book,...}".
    const CliResult all = run_cli({"--help-all"});
    CHECK(all.code == 0);
    for (const std::string jargon : {"INT:", " INT ", "FLOAT", "TEXT", ":{", "REQUIRED"})
        CHECK_MESSAGE(all.out.find(jargon) == std::string::npos, jargon);
    CHECK(all.out.find("--frames N                  Frames to simulate (default: the scene's settings.frames, 600); "
                       "a whole number from 1 to 10000000") != std::string::npos);
    CHECK(all.out.find("--preset PRESET") != std::string::npos);
    CHECK(all.out.find("one of book, chapter, sweep, pgs, pgs_split, soft_step, soft_step_recycled, "
                       "soft_step_coloured, soft_step_wide, avbd") != std::string::npos);
    for (const std::string command : {"resolve", "run", "inspect", "lesson", "validate", "worksheet", "diff", "bench"})
        CHECK_MESSAGE(all.out.find("\nimpulse-lab " + command) != std::string::npos, command);
}

TEST_CASE("bad flags get one line naming the flag, exit code 2 and no file") {
    struct BadFlag {
        std::vector<std::string> args;
        std::string starts;  // the beginning of the one-line message
    };
    TempDir dir;
    const std::string ruler = cases + "ruler.json";
    const std::string trace = dir.file("t.json").string();
    const std::vector<BadFlag> table{
        {{"resolve", ruler, "--preset", "fast"},
         "impulse-lab: --preset: must be one of book, chapter, sweep, pgs, pgs_split, soft_step, soft_step_recycled, "
         "soft_step_coloured, soft_step_wide, avbd, got \"fast\"; see impulse-lab resolve --help"},
        {{"resolve", ruler, "--preset", "bok"},
         "impulse-lab: --preset: must be one of book, chapter, sweep, pgs, "
         "pgs_split, soft_step, soft_step_recycled, soft_step_coloured, soft_step_wide, avbd, got \"bok\" (did you "
         "mean book?)"},
        {{"resolve", ruler, "--set", "position_method=teleport"},
         "impulse-lab: --set position_method: must be one of \"linear_projection\", \"nonlinear_projection\", "
         "\"velocity_based\", \"relaxation\", \"split_impulse\", \"none\"; got \"teleport\""},
        {{"resolve", ruler, "--set", "angular_limit.factor=-1"},
         "impulse-lab: --set angular_limit.factor: must be >= 0, got -1"},
        {{"resolve", ruler, "--set", "position_epsilon"},
         "impulse-lab: --set: expected name=value, got \"position_epsilon\""},
        {{"resolve", ruler, "--set", "positon_epsilon=1"},
         "impulse-lab: --set positon_epsilon: unknown field (did you mean \"position_epsilon\"?)"},
        {{"resolve", ruler, "--record", "contacts=5"},
         "impulse-lab: --record: there is no contact 5 (this frame has 1 contact, numbered from 0)"},
        {{"resolve", ruler, "--record", "frames=x"},
         "impulse-lab: --record: \"x\" in \"frames=x\" is not a whole number >= 0"},
        {{"resolve", ruler, "--record", "bodies=1"},
         "impulse-lab: --record: expected frames=A..B or contacts=I,J,..., got \"bodies=1\""},
        {{"resolve", ruler, "--trace", dir.file("no/such/dir/t.json").string()},
         "impulse-lab: --trace: cannot write '" + dir.file("no/such/dir/t.json").string() +
             "': No such file or directory"},
        {{"resolve", ruler, "--explian"},
         "impulse-lab: --explian: unknown flag of resolve (did you mean --explain?); see impulse-lab resolve --help"},
        {{"resolve", ruler, "--states", "s.csv"},
         "impulse-lab: --states: unknown flag of resolve (--states is a flag of run); see impulse-lab resolve --help"},
        {{"resolve", ruler, "extra"},
         "impulse-lab: resolve: unexpected argument: extra; see impulse-lab resolve --help"},
        {{"resolve"}, "impulse-lab: CASE is required"},
        {{"frobnicate"},
         "impulse-lab: unknown command \"frobnicate\"; commands: resolve, run, inspect, lesson, validate, worksheet, "
         "diff, bench, help, completion; see impulse-lab help"},
        {{"reslove", ruler}, "impulse-lab: unknown command \"reslove\" (did you mean resolve?)"},
        {{"--hlep"}, "impulse-lab: --hlep: unknown flag (did you mean --help?); see impulse-lab help"},
        {{}, "impulse-lab: a command is required, e.g. impulse-lab lesson 1; see impulse-lab help"},
    };
    for (const BadFlag& b : table) {
        std::vector<std::string> args = b.args;
        if (args.size() > 1 && args[0] == "resolve" && std::find(args.begin(), args.end(), "--trace") == args.end()) {
            args.push_back("--trace");
            args.push_back(trace);
        }
        CAPTURE(b.starts);
        const CliResult r = run_cli(args);
        CHECK(r.code == 2);
        CHECK(r.err.rfind(b.starts, 0) == 0);
        CHECK(count_of(r.err, "\n") == 1);
        CHECK(r.out.empty());
        CHECK_FALSE(std::filesystem::exists(trace));
    }
    CHECK(dir.entries() == 0);
}

TEST_CASE("run simulates a scene, writes its trace and states, and summarises every stage") {
    TempDir dir;
    const std::string trace = dir.file("stack.trace.json").string();
    const std::string states = dir.file("stack.csv").string();
    const CliResult r = run_cli(
        {"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "5", "--trace", trace, "--states", states});
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    for (const char* part :
         {"3 bodies, ground, 5 frames", "frame    time s  contacts  deepest mm   kinetic J", "per frame: integrate",
          "iteration limit (or every sweep) used in", "box2 (highest at the start)"})
        CHECK_MESSAGE(r.out.find(part) != std::string::npos, part);
    const CliResult v = run_cli({"validate", trace});
    CHECK(v.code == 0);
    CHECK(v.out.find("5 frames") != std::string::npos);
    std::ifstream csv(states);
    std::string line;
    std::getline(csv, line);
    CHECK(line == "frame,time,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy");
    std::size_t rows = 0;
    while (std::getline(csv, line)) ++rows;
    CHECK(rows == 3 * (5 + 1));  // every body, the scene as given (frame -1) and 5 frames
}

TEST_CASE(
    "run with contact recycling, in either solve order, writes the same states with and without a trace, and "
    "the trace validates") {
    // Recycling is the world's detection and the order soft step's own: recording what they ran changes no bit.
    // 10 frames: contacts are kept from the second frame on; 60 frames traced 122 MB a run and took 3 minutes of
    // CI under AddressSanitizer, mostly in validating the trace. (Not a structured binding: Debian 12's clang 14
    // does not capture one in doctest's CAPTURE.)
    for (const std::pair<std::string, std::string>& run :
         {std::pair<std::string, std::string>{"soft_step_recycled", R"("recycling")"},
          std::pair<std::string, std::string>{"soft_step_coloured", R"("order": "colours")"},
          std::pair<std::string, std::string>{"soft_step_wide", R"("order": "wide")"}}) {
        const std::string& preset = run.first;
        const std::string& setting = run.second;
        CAPTURE(preset);
        TempDir dir;
        const std::string quiet = dir.file("quiet.csv").string(), traced = dir.file("traced.csv").string();
        const std::string trace = dir.file("t.json").string();
        const std::string scene = IMPULSE_SOURCE_DIR "/scenes/stack_20.json";
        CHECK(run_cli({"run", scene, "--preset", preset, "--frames", "10", "--states", quiet}).code == 0);
        CHECK(
            run_cli({"run", scene, "--preset", preset, "--frames", "10", "--states", traced, "--trace", trace}).code ==
            0);
        const auto text = [](const std::string& path) {
            std::ifstream in(path);
            return std::string(std::istreambuf_iterator<char>(in), {});
        };
        CHECK(text(quiet).size() > 1000);
        CHECK(text(quiet) == text(traced));
        CHECK(text(trace).find(setting) != std::string::npos);
        CHECK(run_cli({"validate", trace}).code == 0);
    }
}

TEST_CASE("run says that a scene's written contacts are for resolve") {
    const CliResult r = run_cli({"run", cases + "two_body_oblique.json", "--frames", "2"});
    CHECK(r.code == 0);
    CHECK(r.err.find("note: the 1 contact(s) written in") != std::string::npos);
}

TEST_CASE("run refuses bad flags and unwritable outputs before simulating, and writes nothing") {
    TempDir dir;
    const std::string scene = IMPULSE_SOURCE_DIR "/scenes/stack_3.json";
    const std::string trace = dir.file("t.json").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> table{
        {{"run", scene, "--frames", "0"},
         "impulse-lab: --frames: must be from 1 to 10000000, got 0; see impulse-lab run --help"},
        {{"run", scene, "--frame", "10"},
         "impulse-lab: --frame: unknown flag of run (did you mean --frames?); see impulse-lab run --help"},
        {{"run", scene, "--frames"},
         "impulse-lab: --frames: needs a value: a whole number from 1 to 10000000; see impulse-lab run --help"},
        {{"run", scene, "--dt"}, "impulse-lab: --dt: needs a value: a number from 1e-06 to 10"},
        {{"run", scene, "--frames", "1e3"},
         "impulse-lab: --frames: expected a whole number from 1 to 10000000, got \"1e3\""},
        {{"run", scene, "--frames", "99999999999999999999"},
         "impulse-lab: --frames: must be from 1 to 10000000, got 99999999999999999999"},
        {{"run", scene, "--dt", "-1"}, "impulse-lab: --dt: must be from 1e-06 to 10, got -1"},
        {{"run", scene, "--dt", "nan"}, "impulse-lab: --dt: must be from 1e-06 to 10, got nan"},
        {{"run", scene, "--dt", "1/60"}, "impulse-lab: --dt: expected a number from 1e-06 to 10, got \"1/60\""},
        {{"run", scene, "--trace", trace, "--max-trace-mb", "nan"},
         "impulse-lab: --max-trace-mb: must be from 1e-06 to 1000000000, got nan"},
        {{"run", scene, "--trace", trace, "--max-trace-mb", "inf"},
         "impulse-lab: --max-trace-mb: must be from 1e-06 to 1000000000, got inf"},
        {{"run", scene, "--states", trace, "--max-states-mb", "0"},
         "impulse-lab: --max-states-mb: must be from 1e-06 to 1000000000, got 0"},
        {{"run", scene, "--states", trace, "--max-states-mb", "1GB"},
         "impulse-lab: --max-states-mb: expected a number from 1e-06 to 1000000000, got \"1GB\""},
        {{"run", scene, "--trace", trace, "--states", dir.file("no/dir/s.csv").string()},
         "impulse-lab: --states: cannot write '" + dir.file("no/dir/s.csv").string() + "': No such file or directory"},
        {{"run", scene, "--trace", trace, "--set", "frames=0"}, "impulse-lab: --set frames: must be >= 1, got 0"},
    };
    for (const auto& [args, starts] : table) {
        const auto& expected = starts;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
        CAPTURE(expected);
        const CliResult r = run_cli(args);
        CHECK(r.code == 2);
        CHECK(r.err.rfind(starts, 0) == 0);
        CHECK(count_of(r.err, "\n") == 1);
        CHECK(r.out.empty());
    }
    CHECK(dir.entries() == 0);
}

namespace {

// A ball on the ground and a bullet: with `bullet_velocity` huge enough the state overflows to infinity (no loader
// check is bypassed: every number is finite and in range as written).
std::string runaway_scene(const std::string& bullet_velocity, const std::string& bullet_position) {
    return R"({"format": "impulse-lab-scene", "ground": {"material": "bouncy"},
  "materials": {"bouncy": {"restitution": 1, "friction": 0}},
  "bodies": [
    {"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, "position": [5, 0.5, 0]},
    {"name": "bullet", "shape": {"type": "sphere", "radius": 0.5}, "position": )" +
           bullet_position + R"(, "velocity": )" + bullet_velocity + R"(, "material": "bouncy"}
  ]})";
}

}  // namespace

TEST_CASE("run stops at the frame that leaves a body non-finite, names the body and the contact, keeps the trace") {
    // Falling at 1e308 m/s onto a restitution-1 ground, the bullet asks for a change of -(1 + 1) v_s = 2e308 m/s:
    // an infinite impulse from contact 0 (bullet / ground) in frame 0.
    TempDir dir;
    const auto scene = dir.write("runaway.json", runaway_scene("[0, -1e308, 0]", "[0, 3, 0]"));
    const std::string trace = dir.file("runaway.trace.json").string();
    const CliResult r = run_cli({"run", scene.string(), "--frames", "10", "--trace", trace});
    CHECK(r.code == impulse::cli::exit_non_finite);
    CHECK(r.err ==
          "impulse-lab: frame 0: body \"bullet\" has a non-finite velocity after resolution (last touched by contact "
          "1: bullet / ground)\n");
    const CliResult v = run_cli({"validate", trace});
    CHECK_MESSAGE(v.code == 0, (v.out + v.err));
}

TEST_CASE("a body that overflows with no contact stops the run with the frames before it written and valid") {
    // 1e308 m/s sideways moves it 1.67e306 m per frame: its position passes the largest double near frame 106.
    TempDir dir;
    const auto scene = dir.write("runaway.json", runaway_scene("[1e308, 0, 0]", "[0, 30, 0]"));
    const std::string trace = dir.file("runaway.trace.json").string();
    const std::string states = dir.file("runaway.csv").string();
    const CliResult r = run_cli({"run", scene.string(), "--frames", "500", "--trace", trace, "--states", states});
    CHECK(r.code == impulse::cli::exit_non_finite);
    CHECK(r.err.find("body \"bullet\" has a non-finite position after resolution (no contact touched it this "
                     "frame)") != std::string::npos);
    const std::size_t at = r.err.find("frame ") + 6;
    const int frame = std::stoi(r.err.substr(at));
    CHECK(frame > 100);
    const CliResult v = run_cli({"validate", trace});
    CHECK_MESSAGE(v.code == 0, (v.out + v.err));
    CHECK(v.out.find(std::to_string(frame) + " frames") != std::string::npos);  // frames 0 .. frame - 1
    std::ifstream csv(states);
    std::string line;
    std::size_t rows = 0;
    while (std::getline(csv, line)) ++rows;
    CHECK(rows == 1 + 2 * (static_cast<std::size_t>(frame) + 1));  // header, frame -1 and frames before it
}

TEST_CASE("resolve and worksheet stop where run stops on a non-finite body, say so and write nothing") {
    TempDir dir;
    // resolve: the one frame breaks, so nothing is written.
    const auto falling = dir.write("falling.json", runaway_scene("[0, -1e308, 0]", "[0, 0.4, 0]"));
    const CliResult resolved = run_cli({"resolve", falling.string(), "--trace", dir.file("r.json").string()});
    CHECK(resolved.code == impulse::cli::exit_non_finite);
    CHECK(resolved.err ==
          "impulse-lab: frame 0: body \"bullet\" has a non-finite velocity after resolution (last touched by contact "
          "1: bullet / ground); nothing written\n");
    CHECK_FALSE(std::filesystem::exists(dir.file("r.json")));

    // worksheet refuses: diff could not re-make it. (inspect shows the frames before it: impulse_gui_tests.)
    const auto sideways = dir.write("sideways.json", runaway_scene("[1e308, 0, 0]", "[0, 30, 0]"));
    const std::string sheet = dir.file("sheet.json").string();
    const CliResult worksheet = run_cli({"worksheet", sideways.string(), "--frames", "200", "--out", sheet});
    CHECK(worksheet.code == impulse::cli::exit_non_finite);
    CHECK(worksheet.err.find("; no worksheet written\n") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(sheet));
}

TEST_CASE("a tiny --max-trace-mb stops the recording at a whole frame, says where, and the trace still validates") {
    TempDir dir;
    const std::string trace = dir.file("stack.trace.json").string();
    const CliResult r = run_cli(
        {"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--frames", "60", "--trace", trace, "--max-trace-mb", "2"});
    CHECK(r.code == 0);
    // Said twice: early, once the frames recorded show the run will not fit (run_notes tests), and where it stopped.
    const std::string note = "impulse-lab: note: the trace reached --max-trace-mb 2 at frame ";
    const std::size_t at = r.err.find(note);
    REQUIRE(at != std::string::npos);
    CHECK(r.err.rfind("impulse-lab: note: --trace: at about ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 2);
    const int stopped = std::stoi(r.err.substr(at + note.size()));
    CHECK(stopped > 0);
    CHECK(stopped < 60);
    CHECK(r.out.find("60 frames") != std::string::npos);  // the run itself went on to the end
    const CliResult v = run_cli({"validate", trace});
    CHECK_MESSAGE(v.code == 0, (v.out + v.err));
    CHECK(v.out.find(std::to_string(stopped) + " frames") != std::string::npos);
    // The estimate keeps the file near the bound: never more than a third over it.
    CHECK(std::filesystem::file_size(trace) < 2e6 * 4 / 3);
}

TEST_CASE("--max-trace-mb is refused when it is not a positive number") {
    const CliResult r =
        run_cli({"run", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--trace", "x.json", "--max-trace-mb", "0"});
    CHECK(r.code == impulse::cli::exit_bad_input);
    CHECK(r.err.find("--max-trace-mb") != std::string::npos);
}

TEST_CASE("a file over its stated size limit is refused before it is parsed, and so is one that never ends") {
    TempDir dir;
    // A lesson is text a person writes: 4 MiB at most (formats::max_text_input_bytes).
    const std::string lesson = dir.write("01-huge.md", std::string((4u << 20) + 1, '#')).string();
    const CliResult big = run_cli({"validate", lesson});
    CHECK(big.code == impulse::cli::exit_bad_input);
    CHECK(big.err == "impulse-lab: " + lesson + ": is 4194305 bytes, over the limit of 4 MiB (4194304 bytes)\n");
    // stat says 0 bytes for a device: the limit holds while reading.
    const CliResult endless = run_cli({"inspect", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--headless", "--script",
                                       "/dev/zero", "--screenshot", dir.file("shot.png").string()});
    CHECK(endless.code == impulse::cli::exit_bad_input);
    CHECK(endless.err == "impulse-lab: /dev/zero: goes on past the limit of 4 MiB (4194304 bytes)\n");
    CHECK(dir.entries() == 1);  // the lesson only: no screenshot
}
