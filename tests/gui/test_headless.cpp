// The inspector end to end, headless: SDL's offscreen driver renders the same frames the window shows.
// These tests load Mesa through EGL, so they live in their own program (LeakSanitizer cannot see into
// Mesa after it is unloaded; CMake turns leak checking off for this program only).

#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "formats/trace_json.hpp"
#include "course/lesson.hpp"
#include "model/runs.hpp"
#include "support/png_image.hpp"
#include "support/run_cli.hpp"
#include "support/shipped.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

namespace impulse::test {

namespace {

using impulse::test::ruler;
const std::string sliding_box = IMPULSE_SOURCE_DIR "/scenes/cases/sliding_box.json";

std::string read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

using Image = PngImage;

std::size_t differing_pixels(const Image& a, const Image& b) {
    REQUIRE(a.rgb.size() == b.rgb.size());
    std::size_t n = 0;
    for (std::size_t i = 0; i + 2 < a.rgb.size(); i += 3)
        n += (a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2]) ? 1 : 0;
    return n;
}

}  // namespace

TEST_CASE("a headless script steps through the ruler case, exports, and the exported trace is the engine's") {
    TempDir dir;
    const auto script = dir.write("steps.txt",
                                  "# from basis to angular change and back\n"
                                  "next step 4\n"
                                  "screenshot " +
                                      dir.file("desired.png").string() +
                                      "\n"
                                      "goto phase=position,step=position_change.angular_change\n"
                                      "screenshot " +
                                      dir.file("angular.png").string() +
                                      "\n"
                                      "export table " +
                                      dir.file("angular.csv").string() +
                                      "\n"
                                      "prev step 3\n"
                                      "export trace " +
                                      dir.file("trace.json").string() + "\n");
    const CliResult r = run_cli({"inspect", ruler, "--headless", "--size", "1024x640", "--script", script.string()});
    INFO(r.err);
    REQUIRE(r.code == 0);

    // The trace written from the window is the one `resolve` writes.
    const CliResult resolved = run_cli({"resolve", ruler, "--trace", dir.file("resolved.json").string()});
    REQUIRE(resolved.code == 0);
    CHECK(read(dir.file("trace.json")) == read(dir.file("resolved.json")));

    // The table exported at angular_change ends with that step's rows, marked as changed.
    const std::string csv = read(dir.file("angular.csv"));
    CHECK(csv.starts_with("step,quantity,value,exact,other_frame,formula,equation,meaning,changed\n"));
    CHECK(csv.find("position_change,position_change.angular_change[0],") != std::string::npos);
    CHECK(csv.find("basis,") == std::string::npos);  // an iteration's table starts from its choice, not step 1

    const Image desired = load_png(dir.file("desired.png"));
    const Image angular = load_png(dir.file("angular.png"));
    CHECK(desired.width == 1024);
    CHECK(desired.height == 640);
    CHECK(angular.width == 1024);
    CHECK(angular.height == 640);
    // Not blank: text, panels and the scene make hundreds of colours (antialiasing included).
    CHECK(distinct_colours(desired) > 200);
    // Two different steps give different pictures, by more than a caret's worth of pixels.
    CHECK(differing_pixels(desired, angular) > 5000);
}

TEST_CASE("the same step rendered twice gives the same pixels") {
    TempDir dir;
    for (const char* name : {"a.png", "b.png"}) {
        const CliResult r =
            run_cli({"inspect", sliding_box, "--headless", "--goto", "phase=velocity,iteration=1,step=impulse",
                     "--screenshot", dir.file(name).string()});
        REQUIRE(r.code == 0);
    }
    CHECK(differing_pixels(load_png(dir.file("a.png")), load_png(dir.file("b.png"))) == 0);
}

TEST_CASE("a changed setting re-runs the case and the screenshot shows the new run") {
    TempDir dir;
    const auto script = dir.write("s.txt",
                                  "goto phase=position,step=move_split\n"
                                  "screenshot " +
                                      dir.file("limited.png").string() +
                                      "\n"
                                      "set angular_limit.policy none\n"
                                      "screenshot " +
                                      dir.file("free.png").string() +
                                      "\n"
                                      "export trace " +
                                      dir.file("free.json").string() + "\n");
    const CliResult r = run_cli({"inspect", ruler, "--headless", "--script", script.string()});
    INFO(r.err);
    REQUIRE(r.code == 0);
    const Trace free = formats::read_trace_text(read(dir.file("free.json")));
    CHECK(free.scene.settings.angular_limit.policy == AngularLimitPolicy::none);
    CHECK(differing_pixels(load_png(dir.file("limited.png")), load_png(dir.file("free.png"))) > 0);
}

TEST_CASE("a bad script line is reported with its line number and nothing is written") {
    TempDir dir;
    const auto script =
        dir.write("bad.txt", "next step\n\njump ahead\nscreenshot " + dir.file("x.png").string() + "\n");
    const CliResult r = run_cli({"inspect", ruler, "--headless", "--script", script.string()});
    CHECK(r.code == 2);
    CHECK(r.err.starts_with("impulse-lab: " + script.string() + ": line 3: unknown action \"jump\""));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(dir.file("x.png")));
}

TEST_CASE("stepping past the end of the trace in a script is an error naming the line") {
    TempDir dir;
    const auto script = dir.write("end.txt", "last\nnext step\n");
    const CliResult r = run_cli({"inspect", ruler, "--headless", "--script", script.string()});
    CHECK(r.code == 2);
    CHECK(r.err.find("line 2: next step: already at the end of the trace") != std::string::npos);
}

TEST_CASE("inspect rejects bad flags with one line naming the flag") {
    TempDir dir;
    const std::string png = dir.file("x.png").string();
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const Case cases[] = {
        {{"inspect", ruler, "--headless"}, "impulse-lab: --headless: nothing to render"},
        {{"inspect", ruler, "--headless", "--size", "big", "--screenshot", png},
         "impulse-lab: --size: expected WIDTHxHEIGHT"},
        {{"inspect", ruler, "--headless", "--size", "100x100", "--screenshot", png}, "impulse-lab: --size: each side"},
        {{"inspect", ruler, "--headless", "--goto", "phase=sideways", "--screenshot", png},
         "impulse-lab: --goto: phase must be preparation, position or velocity"},
        {{"inspect", ruler, "--headless", "--goto", "iteration=99", "--screenshot", png},
         "impulse-lab: --goto: the position phase of frame 0 has iterations 0..0, not 99"},
        {{"inspect", ruler, "--headless", "--screenshot", dir.file("missing/x.png").string()},
         "impulse-lab: --screenshot:"},
        {{"inspect", ruler, "--headless", "--frames", "5", "--screenshot", png}, "impulse-lab: --frames: a case"},
    };
    for (const Case& c : cases) {
        const CliResult r = run_cli(c.args);
        INFO(c.args.back() << " / " << r.err);
        CHECK(r.code == 2);
        CHECK(r.err.starts_with(c.message));
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
    CHECK(dir.entries() == 0);
}

TEST_CASE("without a display and without --headless, inspect says so in one line") {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    const std::string saved_display = display ? display : "", saved_wayland = wayland ? wayland : "";
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    const CliResult r = run_cli({"inspect", ruler});
    if (display) ::setenv("DISPLAY", saved_display.c_str(), 1);
    if (wayland) ::setenv("WAYLAND_DISPLAY", saved_wayland.c_str(), 1);
    CHECK(r.code == 2);
    CHECK(r.err ==
          "impulse-lab: inspect: there is no display to open a window on (DISPLAY is not set); add "
          "--headless with --screenshot or --script to render PNG files instead\n");
}

TEST_CASE("a scene is simulated first, then inspected frame by frame") {
    TempDir dir;
    const auto script = dir.write("s.txt", "goto frame=2\nexport trace " + dir.file("t.json").string() + "\n");
    const CliResult r = run_cli({"inspect", IMPULSE_SOURCE_DIR "/scenes/stack_3.json", "--headless", "--frames", "3",
                                 "--script", script.string()});
    INFO(r.err);
    REQUIRE(r.code == 0);
    const Trace trace = formats::read_trace_text(read(dir.file("t.json")));
    CHECK(trace.frames.size() == 3);
    const Scene scene = formats::read_scene_text(read(IMPULSE_SOURCE_DIR "/scenes/stack_3.json"));
    CHECK(trace == model::run_frames(scene, TraceFilter{}, 3));
}

TEST_CASE("--bench-frames prints frame-time percentiles and the time the file took to open") {
    const CliResult r = run_cli({"inspect", ruler, "--headless", "--bench-frames", "5"});
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK(r.out.starts_with("bench: 5 frames at 1280x800 headless"));
    CHECK(r.out.find("opened in ") != std::string::npos);
    CHECK(r.out.find("frame time ms: p50 ") != std::string::npos);
}

}  // namespace impulse::test

namespace impulse::test {

TEST_CASE("every lesson runs headless: annotated text, its trace and one screenshot per step") {
    TempDir dir;
    ::setenv("XDG_CONFIG_HOME", dir.file("cfg").c_str(), 1);
    const std::vector<std::filesystem::path> files = course::lesson_files(IMPULSE_SOURCE_DIR "/lessons");
    REQUIRE(files.size() == 14);
    for (const std::filesystem::path& file : files) {
        const course::Lesson lesson = course::read_lesson(file);
        const std::string number = std::to_string(lesson.number);
        const auto out = dir.file("lesson-" + number);
        const CliResult r = run_cli({"lesson", number, "--headless", "--out", out.string(), "--size", "640x400"});
        INFO(file.filename().string() << ": " << r.err);
        REQUIRE(r.code == 0);
        CHECK(r.out.starts_with("Lesson " + number + " · " + lesson.title));
        std::size_t pictures = 0;
        for (const auto& entry : std::filesystem::directory_iterator(out))
            if (entry.path().extension() == ".png") {
                ++pictures;
                const Image image = load_png(entry.path());
                CHECK(image.width == 640);
                CHECK(distinct_colours(image) > 100);
            }
        CHECK(pictures == lesson.steps.size());
        CHECK(formats::read_trace_text(read(out / "trace.json")).frames.size() >= 1);
    }
    // Showing answers in text does not count as answering: no progress is written.
    CHECK_FALSE(std::filesystem::exists(dir.file("cfg/impulse-lab/progress.json")));
    ::unsetenv("XDG_CONFIG_HOME");
}

TEST_CASE("without a display a lesson falls back to text and pictures, and says so") {
    TempDir dir;
    const char* display = std::getenv("DISPLAY");
    const std::string saved = display ? display : "";
    ::unsetenv("DISPLAY");
    const CliResult r = run_cli({"lesson", "1", "--out", dir.file("one").string()});
    if (display) ::setenv("DISPLAY", saved.c_str(), 1);
    CHECK(r.code == 0);
    CHECK(r.err.find("note: no display") != std::string::npos);
    CHECK(std::filesystem::exists(dir.file("one/trace.json")));
}

TEST_CASE("inspect shows a run up to the frame that left a body non-finite, with a note naming it") {
    // Moving sideways at 1e308 m/s, the bullet's position passes the largest double a little after frame 100.
    TempDir dir;
    const auto scene = dir.write("sideways.json", R"({"bodies": [{"name": "bullet", "shape": {"type": "sphere",
        "radius": 0.5}, "position": [0, 30, 0], "velocity": [1e308, 0, 0]}]})");
    const std::string shot = dir.file("shot.png").string();
    const CliResult r = run_cli({"inspect", scene.string(), "--frames", "200", "--headless", "--screenshot", shot});
    CHECK(r.code == 0);
    CHECK(r.err.find("impulse-lab: note: the run stopped at frame ") == 0);
    CHECK(r.err.find("body \"bullet\" has a non-finite position after resolution (no contact touched it this "
                     "frame); the frames before it are shown\n") != std::string::npos);
    CHECK(std::filesystem::exists(shot));
}

TEST_CASE("inspect says which frames it recorded when the trace budget cut it, at the start and after every re-run") {
    TempDir dir;
    const auto script = dir.write("s.txt", "set velocity_epsilon 0.00001\ngoto frame=0\n");
    const CliResult r = run_cli({"inspect", IMPULSE_SOURCE_DIR "/scenes/box_resting.json", "--max-trace-mb", "0.1",
                                 "--headless", "--script", script.string()});
    CHECK(r.code == 0);
    CHECK(r.err ==
          "impulse-lab: note: recorded frames 0..2 of 0..59 (the trace reached --max-trace-mb 0.1 at frame "
          "3); raise --max-trace-mb or narrow --record to see later frames\n"
          "impulse-lab: note: " +
              script.string() +
              ": line 1: re-ran with velocity_epsilon=0.00001: recorded frame 0 of 0..59 (the trace "
              "reached --max-trace-mb 0.1 at frame 1)\n");
}

TEST_CASE("a script's export table - and --screenshot - put the table and the picture on standard output") {
    // The same bytes as the files the same script and flag write; what inspect says goes to stderr then.
    TempDir dir;
    const auto to_file = dir.write(
        "to-file.txt", "goto phase=velocity,step=impulse\nexport table " + dir.file("table.csv").string() + "\n");
    REQUIRE(run_cli({"inspect", ruler, "--headless", "--script", to_file.string()}).code == 0);
    const auto to_stdout = dir.write("to-stdout.txt", "goto phase=velocity,step=impulse\nexport table -\n");
    const CliResult table = run_cli({"inspect", ruler, "--headless", "--script", to_stdout.string()});
    CHECK(table.code == 0);
    CHECK(table.out == read(dir.file("table.csv")));

    REQUIRE(run_cli({"inspect", ruler, "--headless", "--screenshot", dir.file("shot.png").string()}).code == 0);
    const CliResult picture = run_cli({"inspect", ruler, "--headless", "--screenshot", "-"});
    CHECK(picture.code == 0);
    CHECK(picture.out == read(dir.file("shot.png")));
    CHECK(dir.entries() == 4);  // two scripts, the table and the picture: no file named "-"
}

}  // namespace impulse::test
